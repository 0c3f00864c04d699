#include "targeting.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "world/voxel_ray.h"

namespace terrasol {
namespace {}  // namespace

std::optional<Target> targetBlock(const World& world, glm::dvec3 eye, glm::dvec3 direction, double reach) {
  const double length = glm::length(direction);
  if (!(length > 1e-9)) return std::nullopt;  // also catches NaN
  const glm::dvec3 dir = direction / length;
  const BlockRegistry& blocks = world.blocks();
  const BlockShapes* shapes = world.shapes();
  std::optional<BoxHit> shaped;  // the hit on a shaped block's boxes
  const auto step = walkVoxels(eye, dir, reach, [&](const VoxelStep& s) {
    if (!inWorldHeight(s.cell.y)) return false;
    const BlockId state = world.getBlock({s.cell.x, s.cell.y, s.cell.z});
    const BlockType& type = blocks[state];
    if (type.shape == BlockShape::None || type.shape == BlockShape::Liquid) return false;
    if (!shapes || type.shape != BlockShape::Model) return true;
    // A shaped block is hit only where the ray meets one of its boxes.
    shaped = firstBoxHit(shapes->boxes(state), s.cell, eye, dir);
    if (shaped && shaped->t > reach) shaped.reset();
    return shaped.has_value();
  });
  if (!step) return std::nullopt;
  const BlockPos block{step->cell.x, step->cell.y, step->cell.z};
  const glm::ivec3 normal = shaped ? shaped->normal : step->normal;
  const double distance = shaped ? shaped->t : step->t;
  return Target{block, normal, block.offset(normal.x, normal.y, normal.z), distance};
}

// The box the outline is drawn around: the union of the state's boxes, or the whole cell.
WorldBox outlineOf(const World& world, const BlockPos& block) {
  const glm::dvec3 corner(block.x, block.y, block.z);
  const BlockShapes* shapes = world.shapes();
  if (!shapes) return {corner, corner + glm::dvec3(1.0)};
  const std::vector<ShapeBox>& boxes = shapes->boxes(world.getBlock(block));
  if (boxes.empty()) return {corner, corner + glm::dvec3(1.0)};
  glm::dvec3 lo(1e30), hi(-1e30);
  for (const ShapeBox& b : boxes) {
    lo = glm::min(lo, glm::dvec3(b.from[0], b.from[1], b.from[2]) / 16.0);
    hi = glm::max(hi, glm::dvec3(b.to[0], b.to[1], b.to[2]) / 16.0);
  }
  return {corner + lo, corner + hi};
}

}  // namespace terrasol
