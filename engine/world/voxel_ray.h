#pragma once
// Amanatides and Woo's grid traversal: the cells a ray passes through, in order, each with the
// distance at which the ray enters it and the face it enters through. What block picking and the
// ray-traced shadow truth share.

#include <cmath>
#include <optional>

#include <glm/vec3.hpp>

namespace terrasol {

struct VoxelStep {
  glm::ivec3 cell;
  double t = 0.0;     // distance along the ray where it enters the cell (0 for the first)
  glm::ivec3 normal;  // outward normal of the face it entered through; zero for the first cell
};

// Calls `visit(const VoxelStep&)` for every cell from `origin`'s along unit `dir` up to `maxDistance`
// until it returns true; returns that step, or nothing. A zero component of `dir` never steps on its
// axis (no division by zero, no NaN).
template <class Visit>
std::optional<VoxelStep> walkVoxels(glm::dvec3 origin, glm::dvec3 dir, double maxDistance, Visit&& visit) {
  VoxelStep s{glm::ivec3(std::floor(origin.x), std::floor(origin.y), std::floor(origin.z)), 0.0, glm::ivec3(0)};
  glm::ivec3 step;
  glm::dvec3 tMax, tDelta;
  for (int a = 0; a < 3; ++a) {
    step[a] = dir[a] > 0.0 ? 1 : -1;
    const double d = std::abs(dir[a]);
    const double boundary = dir[a] > 0.0 ? std::floor(origin[a]) + 1.0 - origin[a] : origin[a] - std::floor(origin[a]);
    tDelta[a] = d > 1e-12 ? 1.0 / d : 1e300;
    tMax[a] = d > 1e-12 ? boundary / d : 1e300;
  }
  while (s.t <= maxDistance) {
    if (visit(static_cast<const VoxelStep&>(s))) return s;
    const int a = tMax.x < tMax.y ? (tMax.x < tMax.z ? 0 : 2) : (tMax.y < tMax.z ? 1 : 2);
    s.t = tMax[a];
    tMax[a] += tDelta[a];
    s.cell[a] += step[a];
    s.normal = glm::ivec3(0);
    s.normal[a] = -step[a];
  }
  return std::nullopt;
}

}  // namespace terrasol
