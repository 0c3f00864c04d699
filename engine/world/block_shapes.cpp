#include "world/block_shapes.h"

namespace terrasol {

BlockShapes::BlockShapes(const BlockRegistry& blocks)
    : boxes_(blocks.size()),
      shapeOccludesLight_(blocks.size()),
      opaqueModel_(blocks.size()),
      lightSides_(blocks.size()),
      opaqueCubes_(blocks.opaqueCubes()) {
  for (BlockId s = 0; s < blocks.size(); ++s) {
    shapeOccludesLight_[s] = blocks[s].shapeOccludesLight;
    opaqueModel_[s] = blocks[s].shape == BlockShape::Model && blocks[s].layer == RenderLayer::Opaque;
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
  if (opaqueModel_[state]) {
    const auto& b = boxes_[state];
    opaqueCubes_[state] = b.size() == 1 && b[0].from == ShapeBox{}.from && b[0].to == ShapeBox{}.to ? 1 : 0;
  }
}

}  // namespace terrasol
