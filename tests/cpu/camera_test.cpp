#include "core/camera.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_access.hpp>

namespace terrasol {
namespace {

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

TEST(Camera, ExtremeViewsGiveFiniteMatrices) {
  const glm::vec3 p(1.0f, 64.0f, -3.0f);
  for (const glm::vec3 target :
       {p + glm::vec3(0, 10, 0), p - glm::vec3(0, 10, 0), p, p + glm::vec3(1e-9f, 1, 0)}) {
    Camera camera{p, target};
    EXPECT_TRUE(finite(camera.view())) << target.y;
  }
  for (const float fov : {0.0f, 1.0f, 170.0f, 180.0f, -5.0f}) {
    Camera camera;
    camera.fovDegrees = fov;
    EXPECT_TRUE(finite(camera.projection(16.0f / 9.0f))) << fov;
    EXPECT_TRUE(finite(camera.projection(0.0f))) << fov;
  }
}

TEST(Camera, LooksWhereAsked) {
  Camera camera{{0, 0, 0}, {10, 0, 0}};
  const glm::vec4 ahead = camera.view() * glm::vec4(10, 0, 0, 1);
  EXPECT_NEAR(ahead.z, -10.0f, 1e-5f);  // GL looks down -Z in view space
  EXPECT_NEAR(ahead.x, 0.0f, 1e-5f);
  Camera down{{0, 5, 0}, {0, 0, 0}};
  const glm::vec4 below = down.view() * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(below.z, -5.0f, 1e-5f);
}

}  // namespace
}  // namespace terrasol
