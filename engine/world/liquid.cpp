#include "world/liquid.h"

#include <cmath>

namespace terrasol {

std::optional<std::size_t> liquidIn(const World& world, const BlockPos& pos) {
  const BlockRegistry& blocks = world.blocks();
  const BlockId id = world.getBlock(pos);
  if (blocks[id].shape == BlockShape::Liquid) return blocks.blockIndex(id);
  if (blocks.holdsWater()[id]) return blocks.blockIndex(blocks.waterState());
  return std::nullopt;
}

bool isLiquid(const World& world, const BlockPos& pos) {
  return liquidIn(world, pos).has_value();
}

std::optional<double> liquidSurfaceAbove(const World& world, glm::dvec3 point) {
  if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) return std::nullopt;
  if (point.y < kMinY || point.y >= kMaxY) return std::nullopt;
  const BlockPos start = BlockPos::containing(point.x, point.y, point.z);
  const std::optional<std::size_t> liquid = liquidIn(world, start);
  if (!liquid) return std::nullopt;
  BlockPos top = start;
  while (top.y + 1 < kMaxY && liquidIn(world, top.offset(0, 1, 0)) == liquid) top = top.offset(0, 1, 0);
  const double surface = top.y + 1.0 - kLiquidSurfaceDrop32 / 32.0;
  if (point.y >= surface) return std::nullopt;  // in the top cell, above its lowered surface
  return surface;
}

bool underWater(const World& world, glm::dvec3 point) {
  if (!liquidSurfaceAbove(world, point)) return false;
  const std::optional<std::size_t> liquid = liquidIn(world, BlockPos::containing(point.x, point.y, point.z));
  return liquid && world.blocks().block(*liquid).name.ends_with("water");
}

}  // namespace terrasol
