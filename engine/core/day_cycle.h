#pragma once
// The day-night model behind the renderer's sky and lighting uniforms: world time -> sun and moon
// directions, the shadow-casting light and the sky, fog and disc colours. Pure math, no GL. Every
// result is finite, and every direction unit length, for any tick and any sun path rotation.
//
// Time: kTicksPerDay ticks a day, as in Minecraft: 0 sunrise, 6000 noon, 12000 sunset, 18000 midnight.
// The sun moves at a constant angular speed (vanilla's slightly stretched day is left out).
//
// Directions are in world space, y up. The sun rises in the east (+x), passes straight overhead at noon
// and sets in the west (-x). `sunPathRotationDegrees` (clamped to [-90, 90]) tilts that path by a
// right-handed rotation about +x, like shader packs' sunPathRotation: at noon with -30 the sun stands
// 30 degrees from the zenith towards -z (Minecraft's north); with +30, towards +z. The moon is always
// exactly opposite the sun.

#include <cstdint>
#include <glm/glm.hpp>

namespace terrasol {

inline constexpr std::int64_t kTicksPerDay = 24000;
inline constexpr std::int64_t kSunrise = 0;
inline constexpr std::int64_t kNoon = kTicksPerDay / 4;
inline constexpr std::int64_t kSunset = kTicksPerDay / 2;
inline constexpr std::int64_t kMidnight = kTicksPerDay * 3 / 4;
static_assert(kNoon == 6000 && kSunset == 12000 && kMidnight == 18000);

// skyBrightness at night; by day it is 1. Vanilla's sky light never drops below this either.
inline constexpr float kNightSkyBrightness = 0.2f;

// The sky gradient's radiance scale against the sun's ~3 (lightColor): the sky shader's and the fog
// under water's.
inline constexpr float kSkyRadiance = 3.0f;

struct DayState {
  double dayFraction;       // 0..1, ticks mod kTicksPerDay / kTicksPerDay
  glm::vec3 toSun, toMoon;  // unit vectors towards them (world space, y up)
  // Unit: toSun while the sun is above the horizon (sun elevation >= 0), else toMoon.
  glm::vec3 toShadowLight;
  bool sunIsShadowLight;
  // Linear RGB radiance of the shadow-casting light, already multiplied by directStrength: warm white sun
  // (~3 at noon), dim bluish moon (~0.3). Both fade to exactly 0 as their body reaches the horizon, so
  // the sun -> moon switch there has no pop.
  glm::vec3 lightColor;
  float directStrength;             // 0..1, that fade alone (1 well above the horizon, 0 at/below it)
  glm::vec3 skyZenith, skyHorizon;  // linear RGB sky gradient (orange-red horizon at sunrise/sunset)
  glm::vec3 fogColor;               // linear RGB
  glm::vec3 sunColor, moonColor;    // linear RGB for drawing the discs, same scale as lightColor unfaded
  float starVisibility;             // 0 by day, 1 at night, smooth through dusk
  float skyBrightness;              // vanilla-like sky light multiplier: 1 by day, 0.2 at night
};

// Negative ticks are accepted too (they count back from tick 0).
DayState dayStateAt(std::int64_t ticks, float sunPathRotationDegrees);

}  // namespace terrasol
