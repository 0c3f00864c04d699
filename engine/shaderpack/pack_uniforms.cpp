#include "shaderpack/pack_uniforms.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

namespace terrasol {
namespace {

constexpr std::int64_t kTicksPerDay = 24000;

glm::mat4 rotateDegrees(const glm::mat4& m, float degrees, const glm::vec3& axis) {
  return glm::rotate(m, glm::radians(degrees), axis);
}

}  // namespace

PackTime packTimeAt(std::int64_t ticks) {
  PackTime t;
  const std::int64_t inDay = ((ticks % kTicksPerDay) + kTicksPerDay) % kTicksPerDay;
  const std::int64_t day = (ticks - inDay) / kTicksPerDay;
  t.worldTime = static_cast<int>(inDay);
  t.worldDay = static_cast<int>(day);
  t.moonPhase = static_cast<int>(((day % 8) + 8) % 8);
  // Vanilla: d = frac(t / 24000 - 0.25); angle = (2d + 0.5 - cos(pi d) / 2) / 3.
  double d = static_cast<double>(inDay) / static_cast<double>(kTicksPerDay) - 0.25;
  d -= std::floor(d);
  t.skyAngle = static_cast<float>((d * 2.0 + (0.5 - std::cos(d * std::numbers::pi) / 2.0)) / 3.0);
  t.sunAngle = t.skyAngle < 0.75f ? t.skyAngle + 0.25f : t.skyAngle - 0.75f;
  t.shadowAngle = t.day() ? t.sunAngle : t.sunAngle - 0.5f;
  return t;
}

glm::mat4 packSkyRotation(const PackTime& time, float sunPathRotationDegrees) {
  // Vanilla's sky: Ry(-90), the path's tilt about z, then the celestial angle about x.
  glm::mat4 sky = rotateDegrees(glm::mat4(1.0f), -90.0f, {0, 1, 0});
  sky = rotateDegrees(sky, sunPathRotationDegrees, {0, 0, 1});
  return rotateDegrees(sky, time.skyAngle * 360.0f, {1, 0, 0});
}

PackCelestial packCelestial(const PackTime& time, float sunPathRotationDegrees,
                            const glm::mat4& gbufferModelView) {
  const glm::mat4 sky = gbufferModelView * packSkyRotation(time, sunPathRotationDegrees);
  PackCelestial c;
  c.sunPosition = glm::vec3(sky * glm::vec4(0, 100, 0, 0));
  c.moonPosition = glm::vec3(sky * glm::vec4(0, -100, 0, 0));
  c.shadowLightPosition = time.day() ? c.sunPosition : c.moonPosition;
  c.upPosition = glm::vec3(gbufferModelView * glm::vec4(0, 100, 0, 0));
  return c;
}

glm::mat4 packShadowModelView(const PackTime& time, float sunPathRotationDegrees, float intervalSize,
                              const glm::dvec3& camera) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -100.0f});
  m = rotateDegrees(m, 90.0f, {1, 0, 0});
  m = rotateDegrees(m, time.skyAngle * -360.0f + (time.day() ? 0.0f : 180.0f), {0, 0, 1});
  m = rotateDegrees(m, sunPathRotationDegrees, {1, 0, 0});
  if (intervalSize > 0.0f) {
    // Java's float %: the remainder takes the dividend's sign.
    const auto offset = [&](double c) {
      return std::fmod(static_cast<float>(c), intervalSize) - intervalSize / 2.0f;
    };
    m = glm::translate(m, {offset(camera.x), offset(camera.y), offset(camera.z)});
  }
  return m;
}

glm::mat4 packShadowProjection(float shadowDistance) {
  return glm::ortho(-shadowDistance, shadowDistance, -shadowDistance, shadowDistance, 0.05f, 256.0f);
}

}  // namespace terrasol
