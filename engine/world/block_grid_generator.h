#pragma once
// Every block laid out in a grid, as Minecraft's debug world lays out its states: a contact sheet for
// players, pack authors and goldens. "blocks" stands each block's default state (out of water) two
// cells apart on a grass floor; "lights" stands each block that gives light, in its brightest state,
// in a closed stone room with no sky.

#include <memory>
#include <vector>

#include "world/coords.h"
#include "world/generator.h"

namespace terrasol {

struct BlockGrid {
  static constexpr int kFloorY = 63;  // the grid stands at y = 64
  static constexpr int kSpacing = 2;
  std::vector<BlockId> states;
  int columns = 1;
  bool room = false;  // "lights": walls and a ceiling round the grid

  static BlockGrid of(const BlockRegistry& blocks, bool lightsOnly);
  BlockPos at(std::size_t i) const;
  // The grid's extent in x and z, from 0: its last cell plus one.
  int width() const { return (columns - 1) * kSpacing + 1; }
  int depth() const;
};

std::unique_ptr<ChunkGenerator> makeBlockGridGenerator(const BlockRegistry& blocks, bool lightsOnly);

}  // namespace terrasol
