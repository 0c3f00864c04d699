#pragma once
// Light through shaped blocks (World::shapes, BlockShapes::lightFaces) flattened for the flood fill:
// per block id and side its covered part's index, the sides covered whole, and which pairs of parts
// close a side between them. Internal to engine/light.

#include <cstdint>
#include <vector>

#include "world/world.h"

namespace terrasol::light {

struct LightFaces {
  std::vector<std::uint8_t> faces;   // block * 6 + side (Direction): index of its covered part, 0 none
  std::vector<std::uint8_t> full;    // per block: the sides covered whole, bits by Direction
  std::vector<std::uint8_t> closed;  // a * count + b: 1 when parts a and b together cover the side
  std::size_t count = 1;

  // Without shapes, no block has any.
  explicit LightFaces(const World& world) : faces(world.blocks().size() * 6), full(world.blocks().size()) {
    const BlockShapes* shapes = world.shapes();
    if (!shapes) {
      closed = {0};
      return;
    }
    for (BlockId b = 0; b < world.blocks().size(); ++b) {
      for (int d = 0; d < 6; ++d)
        faces[b * 6u + static_cast<unsigned>(d)] = shapes->lightFaces()[b][static_cast<std::size_t>(d)];
      full[b] = shapes->lightSides()[b];
    }
    const auto& masks = shapes->lightFaceMasks();
    count = masks.size();
    closed.resize(count * count);
    for (std::size_t a = 0; a < count; ++a)
      for (std::size_t c = 0; c < count; ++c) closed[a * count + c] = (masks[a] | masks[c]).all() ? 1 : 0;
  }
  bool shaped(BlockId b) const {
    for (int d = 0; d < 6; ++d)
      if (faces[b * 6u + static_cast<unsigned>(d)]) return true;
    return false;
  }
  // Whether light crosses from a cell whose side has part `from` into one whose touching side has `to`.
  bool blocks(std::uint8_t from, std::uint8_t to) const { return closed[from * count + to] != 0; }
};

}  // namespace terrasol::light
