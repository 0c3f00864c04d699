#include "targeting.h"

#include <glm/geometric.hpp>

#include "world/voxel_ray.h"

namespace terrasol {

std::optional<Target> targetBlock(const World& world, glm::dvec3 eye, glm::dvec3 direction, double reach) {
  const double length = glm::length(direction);
  if (!(length > 1e-9)) return std::nullopt;  // also catches NaN
  const BlockRegistry& blocks = world.blocks();
  const auto step = walkVoxels(eye, direction / length, reach, [&](const VoxelStep& s) {
    if (!inWorldHeight(s.cell.y)) return false;
    const BlockType& type = blocks[world.getBlock({s.cell.x, s.cell.y, s.cell.z})];
    return type.shape != BlockShape::None && type.shape != BlockShape::Liquid;
  });
  if (!step) return std::nullopt;
  const BlockPos block{step->cell.x, step->cell.y, step->cell.z};
  return Target{block, step->normal, block.offset(step->normal.x, step->normal.y, step->normal.z), step->t};
}

}  // namespace terrasol
