#pragma once
// Octahedral normal encoding (the G-buffer's normals): a unit vector <-> a point of [-1, 1]^2, with a
// sign that is never 0 (the plain sign() sends (0, 0, -1) to (0, 0), which decodes to +z). The
// reference for shaders/lib/octahedral.glsl, which a GL test runs against it on a grid of inputs.
// Plain math, in double so CPU measurements lose nothing.

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace terrasol {

inline glm::dvec2 signNotZero(glm::dvec2 v) {
  return {v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0};
}

inline glm::dvec2 octEncode(glm::dvec3 n) {
  n /= std::max(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1e-20);
  if (n.z >= 0.0) return {n.x, n.y};
  return (1.0 - glm::abs(glm::dvec2(n.y, n.x))) * signNotZero({n.x, n.y});
}

inline glm::dvec3 octDecode(glm::dvec2 e) {
  glm::dvec3 n(e.x, e.y, 1.0 - std::abs(e.x) - std::abs(e.y));
  if (n.z < 0.0) {
    const glm::dvec2 folded = (1.0 - glm::abs(glm::dvec2(n.y, n.x))) * signNotZero({n.x, n.y});
    n.x = folded.x;
    n.y = folded.y;
  }
  return glm::normalize(n);  // |n| >= 1/sqrt(3) on the octahedron: never zero
}

}  // namespace terrasol
