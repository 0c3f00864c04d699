#include "targeting.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "world/voxel_ray.h"

namespace terrasol {
namespace {

struct BoxHit {
  double t;
  glm::ivec3 normal;
};

// Where the unit ray first enters the box (the slab method), and through which face; nothing when it
// misses. Starting inside: t = 0 and no face.
std::optional<BoxHit> rayBox(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 lo, glm::dvec3 hi) {
  double near = 0.0, far = 1e30;
  glm::ivec3 normal(0);
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-12) {
      if (origin[a] < lo[a] || origin[a] > hi[a]) return std::nullopt;
      continue;
    }
    double t0 = (lo[a] - origin[a]) / dir[a], t1 = (hi[a] - origin[a]) / dir[a];
    int side = -1;  // the face entered: the low one when moving up the axis
    if (t0 > t1) {
      std::swap(t0, t1);
      side = 1;
    }
    if (t0 > near) {
      near = t0;
      normal = glm::ivec3(0);
      normal[a] = side;
    }
    far = std::min(far, t1);
    if (near > far) return std::nullopt;
  }
  return BoxHit{near, normal};
}

}  // namespace

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
    shaped.reset();
    const glm::dvec3 corner(s.cell);
    for (const ShapeBox& b : shapes->boxes(state)) {
      const auto hit = rayBox(eye, dir, corner + glm::dvec3(b.from[0], b.from[1], b.from[2]) / 16.0,
                              corner + glm::dvec3(b.to[0], b.to[1], b.to[2]) / 16.0);
      if (hit && hit->t <= reach && (!shaped || hit->t < shaped->t)) shaped = hit;
    }
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
