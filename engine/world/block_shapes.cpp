#include "world/block_shapes.h"

#include <algorithm>

#include "core/error.h"

namespace terrasol {

BlockShapes::BlockShapes(const BlockRegistry& blocks)
    : boxes_(blocks.size()),
      collision_(blocks.size()),
      collisionHeight_(blocks.size()),
      shapeOccludesLight_(blocks.size()),
      opaqueModel_(blocks.size()),
      lightSides_(blocks.size()),
      opaqueCubes_(blocks.opaqueCubes()),
      lightFaces_(blocks.size()),
      minecraftCollision_(blocks.size()) {
  for (BlockId s = 0; s < blocks.size(); ++s) {
    shapeOccludesLight_[s] = blocks[s].shapeOccludesLight;
    opaqueModel_[s] = blocks[s].shape == BlockShape::Model && blocks[s].layer == RenderLayer::Opaque;
    const BlockType& type = blocks[s];
    collisionHeight_[s] = type.collisionHeight > 0 ? type.collisionHeight : 255;  // 255: as the shape
    if (type.passableWhen) {
      const StateValues values = blocks.stateValues(s);
      const auto v = values.find(type.passableWhen->property);
      if (v != values.end() && v->second == type.passableWhen->value) collisionHeight_[s] = 0;
    }
    if (const std::vector<ShapeBox>* boxes = blocks.minecraftCollision(s)) {
      minecraftCollision_[s] = true;
      collision_[s] = *boxes;
    }
    if (blocks[s].shape == BlockShape::Cube) setBoxes(s, {ShapeBox{}});
  }
}

void BlockShapes::setBoxes(BlockId state, std::vector<ShapeBox> boxes) {
  boxes_[state] = std::move(boxes);
  if (!minecraftCollision_[state]) collideWithBoxes(state);
  std::uint8_t sides = 0;
  lightFaces_[state] = {};
  if (shapeOccludesLight_[state]) {
    const FaceCoverage coverage = FaceCoverage::of(boxes_[state]);
    for (int d = 0; d < 6; ++d) {
      const SideMask& mask = coverage.side(static_cast<Direction>(d));
      sides |= mask.all() ? 1u << d : 0u;
      auto known = std::find(faceMasks_.begin(), faceMasks_.end(), mask);
      if (known == faceMasks_.end()) {
        if (faceMasks_.size() == 256) throw Error("more than 255 different light-occluding block sides");
        known = faceMasks_.insert(faceMasks_.end(), mask);
      }
      lightFaces_[state][static_cast<std::size_t>(d)] = static_cast<std::uint8_t>(known - faceMasks_.begin());
    }
  }
  lightSides_[state] = sides;
  if (opaqueModel_[state]) opaqueCubes_[state] = wholeCell(state) ? 1 : 0;
}

// A pack's block collides with its model's boxes, raised to its collision height.
void BlockShapes::collideWithBoxes(BlockId state) {
  collision_[state].clear();
  for (ShapeBox b : boxes_[state]) {
    const bool flat = b.from[0] == b.to[0] || b.from[1] == b.to[1] || b.from[2] == b.to[2];
    if (flat || collisionHeight_[state] == 0) continue;
    if (collisionHeight_[state] != 255) b.to[1] = collisionHeight_[state];
    collision_[state].push_back(b);
  }
}

}  // namespace terrasol
