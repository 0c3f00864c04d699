#pragma once
// Amanatides and Woo's grid traversal: the cells a ray passes through, in order, each with the
// distance at which the ray enters it and the face it enters through, and the ray's hits on a
// block's boxes. What block picking and the ray-traced shadow and reflection truths share.

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <optional>

#include "core/model_units.h"

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
  VoxelStep s{glm::ivec3(std::floor(origin.x), std::floor(origin.y), std::floor(origin.z)), 0.0,
              glm::ivec3(0)};
  glm::ivec3 step;
  glm::dvec3 tMax, tDelta;
  for (int a = 0; a < 3; ++a) {
    step[a] = dir[a] > 0.0 ? 1 : -1;
    const double d = std::abs(dir[a]);
    const double boundary =
        dir[a] > 0.0 ? std::floor(origin[a]) + 1.0 - origin[a] : origin[a] - std::floor(origin[a]);
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

struct BoxHit {
  double t;           // distance along the ray
  glm::ivec3 normal;  // outward normal of the face entered; zero when the ray starts inside
};

// Where the unit ray first enters the box (the slab method), and through which face; nothing when it
// misses. Starting inside: t = 0 and no face.
inline std::optional<BoxHit> rayBox(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 lo, glm::dvec3 hi) {
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

// The nearest hit of the ray on a block's boxes (1/16 of a block, Boxes: a range of ShapeBox) in
// cell `cell`; nothing when it passes them all.
template <class Boxes>
std::optional<BoxHit> firstBoxHit(const Boxes& boxes, glm::ivec3 cell, glm::dvec3 origin, glm::dvec3 dir) {
  std::optional<BoxHit> best;
  const glm::dvec3 corner(cell);
  for (const auto& b : boxes) {
    constexpr double kUnits = kModelUnits;
    const auto hit = rayBox(origin, dir, corner + glm::dvec3(b.from[0], b.from[1], b.from[2]) / kUnits,
                            corner + glm::dvec3(b.to[0], b.to[1], b.to[2]) / kUnits);
    if (hit && (!best || hit->t < best->t)) best = hit;
  }
  return best;
}

}  // namespace terrasol
