// Shader packs' time, sky and shadow uniforms against values worked by hand from vanilla's formulas:
// noon, sunset with the path rotated, midnight, sunrise.

#include "shaderpack/pack_uniforms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace terrasol {
namespace {

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const char* what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << what << " [" << i << "]";
}

TEST(PackUniforms, TimeFollowsVanillasCelestialAngle) {
  const PackTime noon = packTimeAt(6000);
  EXPECT_EQ(noon.worldTime, 6000);
  EXPECT_FLOAT_EQ(noon.skyAngle, 0.0f);
  EXPECT_FLOAT_EQ(noon.sunAngle, 0.25f);
  EXPECT_FLOAT_EQ(noon.shadowAngle, 0.25f);
  // Sunrise: d = 0.75, (1.5 + 0.5 + cos(pi / 4) / 2) / 3 = 0.784518; the day is stretched, so the
  // sun is not at a quarter turn from noon.
  const PackTime sunrise = packTimeAt(0);
  EXPECT_NEAR(sunrise.skyAngle, 0.784518f, 1e-6f);
  EXPECT_NEAR(sunrise.sunAngle, 0.034518f, 1e-6f);
  EXPECT_TRUE(sunrise.day());
  const PackTime sunset = packTimeAt(12000);  // d = 0.25: (0.5 + 0.5 - cos(pi / 4) / 2) / 3
  EXPECT_NEAR(sunset.skyAngle, 0.215482f, 1e-6f);
  const PackTime midnight = packTimeAt(18000);
  EXPECT_FLOAT_EQ(midnight.skyAngle, 0.5f);
  EXPECT_FLOAT_EQ(midnight.sunAngle, 0.75f);
  EXPECT_FALSE(midnight.day());
  EXPECT_FLOAT_EQ(midnight.shadowAngle, 0.25f);
  const PackTime later = packTimeAt(9 * 24000 + 6000);
  EXPECT_EQ(later.worldDay, 9);
  EXPECT_EQ(later.moonPhase, 1);
  const PackTime before = packTimeAt(-1);
  EXPECT_EQ(before.worldTime, 23999);
  EXPECT_EQ(before.worldDay, -1);
  EXPECT_EQ(before.moonPhase, 7);
}

TEST(PackUniforms, TheSunAndMoonStandWhereVanillasSkyPutsThem) {
  const glm::mat4 identity(1.0f);
  const PackCelestial noon = packCelestial(packTimeAt(6000), 0.0f, identity);
  expectNear(noon.sunPosition, {0, 100, 0}, 1e-4f, "noon sun");
  expectNear(noon.moonPosition, {0, -100, 0}, 1e-4f, "noon moon");
  expectNear(noon.shadowLightPosition, noon.sunPosition, 0.0f, "by day the sun");
  expectNear(noon.upPosition, {0, 100, 0}, 0.0f, "up");
  // Sunset, path rotated 30 degrees: the angle 0.215482 turns 77.5735 degrees; cos 0.215185, sin
  // 0.976572. About x: (0, 21.519, 97.657); about z by 30: (-10.759, 18.636, 97.657); about y by -90:
  // (-97.657, 18.636, -10.759). West (-x) and low, leaning to -z.
  const PackCelestial sunset = packCelestial(packTimeAt(12000), 30.0f, identity);
  expectNear(sunset.sunPosition, {-97.657f, 18.636f, -10.759f}, 1e-3f, "sunset sun");
  const PackCelestial midnight = packCelestial(packTimeAt(18000), 0.0f, identity);
  expectNear(midnight.moonPosition, {0, 100, 0}, 1e-4f, "midnight moon");
  expectNear(midnight.shadowLightPosition, midnight.moonPosition, 0.0f, "by night the moon");
  // In eye space: a camera turned 90 degrees about y sees the noon sun still above, the sunset sun
  // ahead or behind.
  const glm::mat4 turned = glm::rotate(identity, glm::radians(90.0f), glm::vec3(0, 1, 0));
  expectNear(packCelestial(packTimeAt(6000), 0.0f, turned).sunPosition, {0, 100, 0}, 1e-4f, "turned noon");
  expectNear(packCelestial(packTimeAt(12000), 0.0f, turned).sunPosition,
             glm::vec3(turned * glm::vec4(-97.657f, 21.519f, 0, 0)), 1e-3f, "turned sunset");
}

// At noon the shadow camera looks straight down; at midnight too (the moon overhead); positions move
// by the camera modulo the interval: with the camera at (5.3, 70.9, -3.2) and interval 2 the offset
// is (0.3, -0.1, -2.2), so the player-space origin lands at (0.3, 2.2, -100.1).
TEST(PackUniforms, TheShadowCameraLooksFromTheLightAndSnapsToItsInterval) {
  const glm::dvec3 camera(5.3, 70.9, -3.2);
  for (const std::int64_t ticks : {6000, 18000}) {
    const glm::mat4 view = packShadowModelView(packTimeAt(ticks), 0.0f, 2.0f, camera);
    expectNear(glm::vec3(view * glm::vec4(0, 1, 0, 0)), {0, 0, 1}, 1e-5f, "up towards the light");
  }
  const glm::mat4 noon = packShadowModelView(packTimeAt(6000), 0.0f, 2.0f, camera);
  expectNear(glm::vec3(noon * glm::vec4(0, 0, 0, 1)), {0.3f, 2.2f, -100.1f}, 1e-4f, "snapped origin");
  const glm::mat4 unsnapped = packShadowModelView(packTimeAt(6000), 0.0f, 0.0f, camera);
  expectNear(glm::vec3(unsnapped * glm::vec4(0, 0, 0, 1)), {0, 0, -100}, 1e-5f, "no interval");
  // Sunset: the light's direction (the sun's, from packCelestial with an identity view) is the shadow
  // camera's +z.
  const PackTime sunset = packTimeAt(11000);
  const glm::vec3 toSun = glm::normalize(packCelestial(sunset, -40.0f, glm::mat4(1.0f)).sunPosition);
  const glm::mat4 view = packShadowModelView(sunset, -40.0f, 0.0f, camera);
  expectNear(glm::vec3(view * glm::vec4(toSun, 0)), {0, 0, 1}, 1e-4f, "towards the sun");

  const glm::mat4 projection = packShadowProjection(160.0f);
  const glm::vec4 nearCorner = projection * glm::vec4(160, 160, -0.05f, 1);
  const glm::vec4 farCorner = projection * glm::vec4(-160, -160, -256, 1);
  expectNear(glm::vec3(nearCorner) / nearCorner.w, {1, 1, -1}, 1e-5f, "near corner");
  expectNear(glm::vec3(farCorner) / farCorner.w, {-1, -1, 1}, 1e-5f, "far corner");
}

}  // namespace
}  // namespace terrasol
