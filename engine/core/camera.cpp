#include "core/camera.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace terrasol {

glm::mat4 Camera::view() const {
  glm::vec3 forward = lookAt - position;
  const float length = glm::length(forward);
  forward = length > 1e-6f ? forward / length : glm::vec3(0.0f, 0.0f, -1.0f);
  // Y is up; looking (nearly) straight along it, take -Z as "up" on screen instead.
  const glm::vec3 up = std::abs(forward.y) > 0.9999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::lookAt(position, position + forward, up);
}

glm::mat4 Camera::projection(float aspect) const {
  const float fov = glm::radians(std::clamp(fovDegrees, 1.0f, 179.0f));
  const float near = std::max(nearPlane, 1e-4f);
  const float far = std::max(farPlane, near * 2.0f);
  return glm::perspective(fov, std::max(aspect, 1e-4f), near, far);
}

}  // namespace terrasol
