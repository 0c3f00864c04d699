#pragma once
// Culling boxes against a view-projection's frustum (the camera's, or the shadow light's box).

#include <array>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace terrasol {

using FrustumPlanes = std::array<glm::vec4, 6>;

// The six planes of a view-projection's frustum (Gribb and Hartmann), inside where dot(p, (x, 1)) >= 0.
inline FrustumPlanes frustumPlanes(const glm::mat4& m) {
  const glm::mat4 t = glm::transpose(m);
  return {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[3] + t[2], t[3] - t[2]};
}

// False when the box from `lo` to `lo + size` is entirely outside one plane.
inline bool boxVisible(const FrustumPlanes& planes, glm::vec3 lo, glm::vec3 hi);
inline bool boxVisible(const FrustumPlanes& planes, glm::vec3 lo, float size) {
  return boxVisible(planes, lo, lo + glm::vec3(size));
}

// False when the box from `lo` to `hi` is entirely outside one plane: the box corner furthest along
// each plane's normal is behind it.
inline bool boxVisible(const FrustumPlanes& planes, glm::vec3 lo, glm::vec3 hi) {
  for (const glm::vec4& p : planes) {
    const glm::vec3 far(p.x > 0.0f ? hi.x : lo.x, p.y > 0.0f ? hi.y : lo.y, p.z > 0.0f ? hi.z : lo.z);
    if (glm::dot(glm::vec3(p), far) + p.w < 0.0f) return false;
  }
  return true;
}

}  // namespace terrasol
