#include "core/camera.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace terrasol {

glm::mat4 Camera::view() const {
  glm::vec3 forward = lookAt - position;
  const float length = glm::length(forward);
  forward = length > 1e-6f ? forward / length : glm::vec3(0.0f, 0.0f, -1.0f);
  // The up hint, unless the view runs (nearly) along it: then Y, or -Z when looking along Y.
  const float upLength = glm::length(up);
  glm::vec3 hint = upLength > 1e-6f ? up / upLength : glm::vec3(0.0f, 1.0f, 0.0f);
  if (std::abs(glm::dot(forward, hint)) > 0.9999f) hint = glm::vec3(0.0f, 1.0f, 0.0f);
  if (std::abs(glm::dot(forward, hint)) > 0.9999f) hint = glm::vec3(0.0f, 0.0f, -1.0f);
  return glm::lookAt(position, position + forward, hint);
}

glm::mat4 Camera::projection(float aspect) const {
  const float fov = glm::radians(std::clamp(fovDegrees, 1.0f, 179.0f));
  const float near = std::max(nearPlane, 1e-4f);
  const float far = std::max(farPlane, near * 2.0f);
  return glm::perspective(fov, std::max(aspect, 1e-4f), near, far);
}

}  // namespace terrasol
