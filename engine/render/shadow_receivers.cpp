#include "render/shadow_receivers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "core/camera.h"

namespace terrasol {
namespace {

// The camera of `view`, at the origin (everything here is relative to the view's eye).
Camera cameraOf(const ViewCone& view) {
  Camera camera;
  camera.lookAt = view.forward;
  camera.up = view.up;
  camera.fovDegrees = view.fovDegrees;
  camera.farPlane = view.farPlane;
  return camera;
}

}  // namespace

ViewCone ViewCone::widened(float degrees, float pullBack) const {
  // Half-angles, each side widened by `degrees`, short of a right angle so the cone stays a cone.
  constexpr float kMaxHalf = glm::radians(85.0f);
  const float vertical = glm::radians(std::clamp(fovDegrees, 1.0f, 170.0f)) * 0.5f;
  const float horizontal = std::atan(std::max(aspect, 1e-3f) * std::tan(vertical));
  const float v = std::min(vertical + glm::radians(degrees), kMaxHalf);
  const float h = std::min(horizontal + glm::radians(degrees), kMaxHalf);
  ViewCone wide = *this;
  wide.fovDegrees = glm::degrees(2.0f * v);
  wide.aspect = std::tan(h) / std::tan(v);
  wide.eye = eye - glm::dvec3(forward) * static_cast<double>(pullBack);
  wide.farPlane = farPlane + pullBack;
  return wide;
}

ShadowReceivers::ShadowReceivers(const ViewCone& view) : origin_(view.eye), floorY_(view.floorY) {
  const Camera camera = cameraOf(view);
  planes_ = frustumPlanes(camera.projection(view.aspect) * camera.view());
}

bool ShadowReceivers::mayShade(glm::dvec3 lo, glm::dvec3 hi, glm::vec3 toLight) const {
  // Per block of descent the light moves this far sideways; a low light sweeps far (clamped, finite).
  const glm::vec3 down = -toLight / std::max(toLight.y, 1e-3f);
  const float drop = static_cast<float>(std::max(hi.y - floorY_, 0.0));
  const glm::vec3 a(lo - origin_), b(hi - origin_);
  const glm::vec3 sweep = down * drop;
  return boxVisible(planes_, glm::min(a, a + sweep), glm::max(b, b + sweep));
}

bool ShadowReceivers::contains(const ViewCone& view) const {
  if (view.floorY < floorY_) return false;
  const glm::vec3 apex(view.eye - origin_);
  for (std::size_t i = 0; i < 5; ++i) {  // inside the sides and beyond the near plane
    if (glm::dot(glm::vec3(planes_[i]), apex) + planes_[i].w < 0.0f) return false;
  }
  const Camera camera = cameraOf(view);
  const glm::mat4 inverse = glm::inverse(camera.projection(view.aspect) * camera.view());
  for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(1, 1)}) {
    const glm::vec4 far = inverse * glm::vec4(corner, 1.0f, 1.0f);
    const glm::vec3 ray = glm::vec3(far) / far.w;  // from the eye (at the origin) to a far corner
    for (std::size_t i = 0; i < 4; ++i) {
      if (glm::dot(glm::vec3(planes_[i]), ray) < 0.0f) return false;
    }
  }
  return true;
}

}  // namespace terrasol
