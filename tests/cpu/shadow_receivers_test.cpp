// Which shadow casters the shadow pass keeps (render/shadow_receivers.h): geometry only, no GL.

#include "render/shadow_receivers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace terrasol {
namespace {

// At the origin looking along +x, the ground (the lowest receiver) at y = 0.
ViewCone camera() {
  ViewCone v;
  v.eye = glm::dvec3(0.0, 20.0, 0.0);
  v.forward = glm::vec3(1.0f, 0.0f, 0.0f);
  v.fovDegrees = 70.0f;
  v.aspect = 16.0f / 9.0f;
  v.farPlane = 128.0f;
  v.floorY = 0.0;
  return v;
}

glm::vec3 light(float x, float y) {
  return glm::normalize(glm::vec3(x, y, 0.0f));
}

TEST(ShadowReceivers, ACasterBehindTheCameraMattersOnlyWhenItsShadowFallsForward) {
  const ShadowReceivers view(camera());
  // 4 to 20 blocks behind the camera, 10..26 up: out of view itself.
  const glm::dvec3 lo(-20.0, 10.0, -8.0), hi(-4.0, 26.0, 8.0);
  // Light from behind and above (45 degrees): the shadow reaches 26 blocks forward by the ground.
  EXPECT_TRUE(view.mayShade(lo, hi, light(-1.0f, 1.0f)));
  // Light from ahead: the shadow falls further back.
  EXPECT_FALSE(view.mayShade(lo, hi, light(1.0f, 1.0f)));
  // Straight down: it stays behind.
  EXPECT_FALSE(view.mayShade(lo, hi, glm::vec3(0.0f, 1.0f, 0.0f)));
  // A low sun behind: far forward, still finite.
  EXPECT_TRUE(view.mayShade(lo, hi, light(-1.0f, 1e-6f)));
}

TEST(ShadowReceivers, CastersInViewAlwaysMatterAndThoseBesideItOnlyWithAMargin) {
  const ShadowReceivers exact(camera());
  EXPECT_TRUE(exact.mayShade({30.0, 0.0, -8.0}, {46.0, 16.0, 8.0}, glm::vec3(0.0f, 1.0f, 0.0f)));
  // 20 blocks ahead, 40 to the side: about 63 degrees off the view's axis, outside its ~51 degree
  // horizontal half-angle; inside once 15 degrees are added.
  const glm::dvec3 lo(20.0, 0.0, 40.0), hi(21.0, 1.0, 41.0);
  EXPECT_FALSE(exact.mayShade(lo, hi, glm::vec3(0.0f, 1.0f, 0.0f)));
  EXPECT_TRUE(ShadowReceivers(camera().widened(15.0f, 0.0f)).mayShade(lo, hi, glm::vec3(0.0f, 1.0f, 0.0f)));
}

TEST(ShadowReceivers, AWidenedViewServesViewsWithinItsMargin) {
  const ShadowReceivers wide(camera().widened(15.0f, 16.0f));
  EXPECT_TRUE(wide.contains(camera()));
  const auto turned = [](float degrees) {
    ViewCone v = camera();
    v.forward = glm::vec3(std::cos(glm::radians(degrees)), 0.0f, std::sin(glm::radians(degrees)));
    return v;
  };
  EXPECT_TRUE(wide.contains(turned(14.0f)));
  EXPECT_FALSE(wide.contains(turned(16.0f)));
  const auto moved = [](glm::dvec3 by) {
    ViewCone v = camera();
    v.eye += by;
    return v;
  };
  EXPECT_TRUE(wide.contains(moved({30.0, 0.0, 0.0})));    // forward: deeper inside
  EXPECT_TRUE(wide.contains(moved({0.0, 0.0, 6.0})));     // sideways, within the pulled-back apex's reach
  EXPECT_FALSE(wide.contains(moved({-17.0, 0.0, 0.0})));  // behind the apex
  ViewCone lower = camera();
  lower.floorY = -1.0;
  EXPECT_FALSE(wide.contains(lower));  // receivers below the floor the casters were chosen for
  ViewCone wider = camera();
  wider.fovDegrees = 110.0f;
  EXPECT_FALSE(wide.contains(wider));
}

}  // namespace
}  // namespace terrasol
