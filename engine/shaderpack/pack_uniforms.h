#pragma once
// The time, sky and shadow uniforms shader packs read, with Minecraft's meaning: its world time and
// celestial angle (vanilla DimensionType.timeOfDay, a day stretched at noon and midnight, unlike
// Terrasol's own even sun), the sun and moon placed as vanilla's sky rotates them (Iris's
// CelestialUniforms), and the shadow camera as OptiFine builds it (Shaders.setCameraShadow). Pure math,
// no GL.

#include <cstdint>
#include <glm/glm.hpp>

namespace terrasol {

struct PackTime {
  int worldTime = 0;  // ticks in the day, 0 sunrise .. 23999
  int worldDay = 0;
  int moonPhase = 0;         // 0..7, one a day
  float skyAngle = 0.0f;     // vanilla's celestial angle: 0 at noon, 0.5 at midnight
  float sunAngle = 0.0f;     // 0 at sunrise, 0.25 noon, 0.5 sunset, 0.75 midnight
  float shadowAngle = 0.0f;  // sunAngle by day (sunAngle <= 0.5), sunAngle - 0.5 by night
  bool day() const { return sunAngle <= 0.5f; }
};
// Negative ticks count back from 0.
PackTime packTimeAt(std::int64_t ticks);

// Vanilla's sky rotation in player space: the sun at +y, the moon at -y.
glm::mat4 packSkyRotation(const PackTime& time, float sunPathRotationDegrees);

// Eye-space positions 100 blocks away (w = 0 directions through `gbufferModelView`).
struct PackCelestial {
  glm::vec3 sunPosition, moonPosition, shadowLightPosition, upPosition;
};
PackCelestial packCelestial(const PackTime& time, float sunPathRotationDegrees,
                            const glm::mat4& gbufferModelView);

// shadowModelView: 100 blocks back towards the shadow light, rotated by the celestial angle (half a
// turn more by night) and the sun path rotation, then moved by the camera's position modulo
// `intervalSize` (OptiFine's shadowIntervalSize, 2 by default) so the map's texels stay put as the
// camera moves. It takes player-space positions (world minus the camera), as packs feed it.
glm::mat4 packShadowModelView(const PackTime& time, float sunPathRotationDegrees, float intervalSize,
                              const glm::dvec3& camera);
// shadowProjection: orthographic, `shadowDistance` each way, near 0.05 and far 256.
glm::mat4 packShadowProjection(float shadowDistance);

}  // namespace terrasol
