#include "world/block_shapes.h"

namespace terrasol {

BlockShapes::BlockShapes(const BlockRegistry& blocks) : boxes_(blocks.size()) {
  for (BlockId s = 0; s < blocks.size(); ++s) {
    if (blocks[s].shape == BlockShape::Cube) boxes_[s] = {ShapeBox{}};
  }
}

}  // namespace terrasol
