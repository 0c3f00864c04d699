#pragma once
// A perspective camera. Safe for every input: a look-at point equal to the position, or a view
// straight up or down, still gives finite matrices.

#include <glm/glm.hpp>

namespace terrasol {

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 lookAt{0.0f, 0.0f, -1.0f};
  float fovDegrees = 70.0f;  // vertical
  float nearPlane = 0.05f;
  float farPlane = 1000.0f;
  glm::vec3 up{0.0f, 1.0f, 0.0f};  // screen-up hint; ignored when (nearly) along the view direction

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

}  // namespace terrasol
