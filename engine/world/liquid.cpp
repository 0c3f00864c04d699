#include "world/liquid.h"

#include <cmath>

namespace terrasol {

bool isLiquid(const World& world, const BlockPos& pos) {
  return world.blocks()[world.getBlock(pos)].shape == BlockShape::Liquid;
}

std::optional<double> liquidSurfaceAbove(const World& world, glm::dvec3 point) {
  if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) return std::nullopt;
  if (point.y < kMinY || point.y >= kMaxY) return std::nullopt;
  const BlockPos start{static_cast<int>(std::floor(point.x)), static_cast<int>(std::floor(point.y)),
                       static_cast<int>(std::floor(point.z))};
  const BlockId liquid = world.getBlock(start);
  if (world.blocks()[liquid].shape != BlockShape::Liquid) return std::nullopt;
  BlockPos top = start;
  while (top.y + 1 < kMaxY && world.getBlock(top.offset(0, 1, 0)) == liquid) top = top.offset(0, 1, 0);
  const double surface = top.y + 1.0 - kLiquidSurfaceDrop32 / 32.0;
  if (point.y >= surface) return std::nullopt;  // in the top cell, above its lowered surface
  return surface;
}

}  // namespace terrasol
