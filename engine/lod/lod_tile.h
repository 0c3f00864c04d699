#pragma once
// Far terrain's tiles. A tile is a square of kLodTileCells x kLodTileCells cells at a level whose cells
// are 2^level blocks wide; each cell summarises the columns it covers: the height of its top, the
// block on it, the water over it and the biome's tint there. Plain C++: sources fill tiles (the generator
// sampled coarsely, lod/generator_tiles.h), a mesher draws them.

#include <array>
#include <cstddef>

#include "core/tint.h"
#include "world/block.h"
#include "world/coords.h"

namespace terrasol {

inline constexpr int kLodTileCells = 32;
inline constexpr int kNoLodHeight = kMinY - 1;  // no ground (a void column), or no water

struct LodCell {
  int top = kNoLodHeight;    // y of the highest ground block
  BlockId surface = kAir;    // the block there
  int water = kNoLodHeight;  // y of the water's surface over the ground, if any
  BlockId waterBlock = kAir;
  ColumnTint tint{};  // the top column's biome colours: its grass, leaves and water

  bool operator==(const LodCell&) const = default;
};

// Which tile: its level and its place in that level's grid (tile (x, z) covers blocks
// [x * spanBlocks(), (x + 1) * spanBlocks()) on each axis).
struct LodTileKey {
  int level = 0;
  int x = 0, z = 0;

  int cellBlocks() const { return 1 << level; }
  int spanBlocks() const { return kLodTileCells << level; }
  int minBlockX() const { return x * spanBlocks(); }
  int minBlockZ() const { return z * spanBlocks(); }
  bool operator==(const LodTileKey&) const = default;
};

struct LodTile {
  LodTileKey key;
  std::array<LodCell, static_cast<std::size_t>(kLodTileCells* kLodTileCells)> cells{};

  LodCell& at(int cx, int cz) { return cells[index(cx, cz)]; }
  const LodCell& at(int cx, int cz) const { return cells[index(cx, cz)]; }

 private:
  static std::size_t index(int cx, int cz) { return static_cast<std::size_t>(cz * kLodTileCells + cx); }
};

}  // namespace terrasol
