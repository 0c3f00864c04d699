#include "core/day_cycle.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace terrasol {
namespace {

// Most colours below are keyed on the sun's height h = toSun.y = sin(elevation), -1..1, as vanilla does:
// it is smooth everywhere and needs no trigonometry.

// Direct light fades in over this many degrees of elevation above the horizon; at 0.015 degrees per tick
// that is ~270 ticks, and lightColor changes by under 2% of its noon value per tick.
constexpr float kHorizonFadeDegrees = 4.0f;

// Vanilla's sky darkening is clamp(2h + 0.2): full day from h = 0.4, full night below h = -0.1.
// The same ramp, smoothed so it has no kinks.
constexpr float kNightBelowHeight = -0.1f;
constexpr float kDayAboveHeight = 0.4f;

// The sunrise/sunset glow peaks with the sun on the horizon and is gone this far above or below it
// (in h); it fades faster below, once the sun no longer lights the air near the ground.
constexpr float kTwilightAbove = 0.35f;
constexpr float kTwilightBelow = 0.15f;
constexpr float kTwilightHorizonMix = 0.8f;
constexpr float kTwilightFogMix = 0.4f;  // fog looks in every direction, not only towards the sun

const glm::vec3 kDayZenith(0.16f, 0.34f, 0.85f);
const glm::vec3 kDayHorizon(0.55f, 0.70f, 0.90f);
const glm::vec3 kNightZenith(0.004f, 0.006f, 0.018f);
const glm::vec3 kNightHorizon(0.010f, 0.014f, 0.032f);
const glm::vec3 kTwilightHorizon(1.0f, 0.38f, 0.12f);

// The sun disc and light: warm white high up, red and dimmer through the long air path near the horizon.
const glm::vec3 kHighSunColor(1.0f, 0.93f, 0.82f);
const glm::vec3 kLowSunColor(1.0f, 0.30f, 0.08f);
constexpr float kSunRadiance = 3.0f;
constexpr float kLowSunDimming = 0.4f;
constexpr float kLowBodyHeight = 0.35f;           // sun and moon look "low" below this height (~20 degrees)
const glm::vec3 kMoonColor(0.24f, 0.27f, 0.36f);  // ~0.3, bluish
constexpr float kLowMoonDimming = 0.6f;

// Stars come out as the sky darkens, between the sun 3 degrees up and ~11.5 degrees down.
constexpr float kStarsGoneAboveHeight = 0.05f;
constexpr float kStarsFullBelowHeight = -0.2f;

// Integer modulo first: a double holds the remainder exactly, so huge tick counts neither drift nor jump.
double dayFractionOf(std::int64_t ticks) {
  std::int64_t inDay = ticks % kTicksPerDay;
  if (inDay < 0) inDay += kTicksPerDay;
  return static_cast<double>(inDay) / static_cast<double>(kTicksPerDay);
}

float sanitizedRotation(float degrees) {
  return std::isfinite(degrees) ? std::clamp(degrees, -90.0f, 90.0f) : 0.0f;
}

// The untilted path is the circle (cos a, sin a, 0), a = 2 pi dayFraction; tilting rotates it about +x.
// Computed in double and normalised, so even the horizon and zenith give unit vectors.
glm::vec3 sunDirection(double dayFraction, float rotationDegrees) {
  const double angle = 2.0 * std::numbers::pi * dayFraction;
  const double tilt = static_cast<double>(rotationDegrees) * std::numbers::pi / 180.0;
  const double up = std::sin(angle);
  const glm::dvec3 direction(std::cos(angle), up * std::cos(tilt), up * std::sin(tilt));
  return glm::vec3(glm::normalize(direction));
}

// 0 at or below the horizon, 1 from kHorizonFadeDegrees up, smooth between.
float horizonFade(float height) {
  const float elevation = glm::degrees(std::asin(std::clamp(height, -1.0f, 1.0f)));
  return glm::smoothstep(0.0f, kHorizonFadeDegrees, elevation);
}

glm::vec3 sunDiscColor(float height) {
  const float high = glm::smoothstep(0.0f, kLowBodyHeight, height);
  return glm::mix(kLowSunColor, kHighSunColor, high) * (kSunRadiance * glm::mix(kLowSunDimming, 1.0f, high));
}

glm::vec3 moonDiscColor(float height) {
  const float high = glm::smoothstep(0.0f, kLowBodyHeight, height);
  return kMoonColor * glm::mix(kLowMoonDimming, 1.0f, high);
}

// A bell around h = 0. Both halves have zero slope at 0, so joining them there leaves no kink.
float twilightAmount(float height) {
  const float width = height >= 0.0f ? kTwilightAbove : kTwilightBelow;
  return 1.0f - glm::smoothstep(0.0f, width, std::abs(height));
}

void setShadowLight(DayState& day) {
  day.sunColor = sunDiscColor(day.toSun.y);
  day.moonColor = moonDiscColor(day.toMoon.y);
  day.sunIsShadowLight = day.toSun.y >= 0.0f;
  day.toShadowLight = day.sunIsShadowLight ? day.toSun : day.toMoon;
  // The switch happens with the sun exactly on the horizon, where both fades are 0: no pop.
  day.directStrength = horizonFade(day.toShadowLight.y);
  day.lightColor = (day.sunIsShadowLight ? day.sunColor : day.moonColor) * day.directStrength;
}

void setSky(DayState& day) {
  const float height = day.toSun.y;
  const float daylight = glm::smoothstep(kNightBelowHeight, kDayAboveHeight, height);
  const float twilight = twilightAmount(height);
  day.skyBrightness = glm::mix(kNightSkyBrightness, 1.0f, daylight);
  day.starVisibility = 1.0f - glm::smoothstep(kStarsFullBelowHeight, kStarsGoneAboveHeight, height);
  day.skyZenith = glm::mix(kNightZenith, kDayZenith, daylight);
  const glm::vec3 plainHorizon = glm::mix(kNightHorizon, kDayHorizon, daylight);
  day.skyHorizon = glm::mix(plainHorizon, kTwilightHorizon, twilight * kTwilightHorizonMix);
  day.fogColor = glm::mix(plainHorizon, kTwilightHorizon, twilight * kTwilightFogMix);
}

}  // namespace

DayState dayStateAt(std::int64_t ticks, float sunPathRotationDegrees) {
  DayState day{};
  day.dayFraction = dayFractionOf(ticks);
  day.toSun = sunDirection(day.dayFraction, sanitizedRotation(sunPathRotationDegrees));
  day.toMoon = -day.toSun;
  setShadowLight(day);
  setSky(day);
  return day;
}

}  // namespace terrasol
