#include "world/block_shapes.h"

namespace terrasol {

BlockShapes::BlockShapes(const BlockRegistry& blocks)
    : boxes_(blocks.size()), shapeOccludesLight_(blocks.size()), lightSides_(blocks.size()) {
  for (BlockId s = 0; s < blocks.size(); ++s) {
    shapeOccludesLight_[s] = blocks[s].shapeOccludesLight;
    if (blocks[s].shape == BlockShape::Cube) setBoxes(s, {ShapeBox{}});
  }
}

void BlockShapes::setBoxes(BlockId state, std::vector<ShapeBox> boxes) {
  boxes_[state] = std::move(boxes);
  std::uint8_t sides = 0;
  if (shapeOccludesLight_[state]) {
    const FaceCoverage coverage = FaceCoverage::of(boxes_[state]);
    for (int d = 0; d < 6; ++d) sides |= coverage.full(static_cast<Direction>(d)) ? 1u << d : 0u;
  }
  lightSides_[state] = sides;
}

}  // namespace terrasol
