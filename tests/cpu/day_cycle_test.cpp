#include "core/day_cycle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/lightmap.h"

namespace terrasol {
namespace {

constexpr std::int64_t kNoon = 6000;
constexpr std::int64_t kSunset = 12000;
constexpr std::int64_t kMidnight = 18000;
constexpr std::int64_t kHuge = 1'000'000'000;
constexpr std::int64_t kMaxTicks = std::numeric_limits<std::int64_t>::max();

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

float biggestChange(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

bool allFinite(const DayState& d) {
  return std::isfinite(d.dayFraction) && finite(d.toSun) && finite(d.toMoon) && finite(d.toShadowLight) &&
         finite(d.lightColor) && std::isfinite(d.directStrength) && finite(d.skyZenith) &&
         finite(d.skyHorizon) && finite(d.fogColor) && finite(d.sunColor) && finite(d.moonColor) &&
         std::isfinite(d.starVisibility) && std::isfinite(d.skyBrightness);
}

void expectSame(const DayState& a, const DayState& b) {
  EXPECT_EQ(a.dayFraction, b.dayFraction);
  EXPECT_EQ(a.toSun, b.toSun);
  EXPECT_EQ(a.lightColor, b.lightColor);
  EXPECT_EQ(a.skyHorizon, b.skyHorizon);
  EXPECT_EQ(a.sunIsShadowLight, b.sunIsShadowLight);
}

TEST(DayCycle, SunRisesEastPassesOverheadAndSetsWest) {
  expectNear(dayStateAt(0, 0.0f).toSun, {1, 0, 0}, 1e-6f);
  expectNear(dayStateAt(kNoon, 0.0f).toSun, {0, 1, 0}, 1e-6f);
  expectNear(dayStateAt(kSunset, 0.0f).toSun, {-1, 0, 0}, 1e-6f);
  const DayState midnight = dayStateAt(kMidnight, 0.0f);
  expectNear(midnight.toMoon, {0, 1, 0}, 1e-6f);
  EXPECT_FALSE(midnight.sunIsShadowLight);
  EXPECT_EQ(midnight.toShadowLight, midnight.toMoon);
  const DayState noon = dayStateAt(kNoon, 0.0f);
  EXPECT_TRUE(noon.sunIsShadowLight);
  EXPECT_EQ(noon.toShadowLight, noon.toSun);
  EXPECT_DOUBLE_EQ(noon.dayFraction, 0.25);
}

TEST(DayCycle, RotationTiltsTheNoonSunByExactlyThatAngle) {
  for (const float rotation : {-90.0f, -45.0f, -30.0f, -5.0f, 5.0f, 30.0f, 60.0f, 90.0f}) {
    const glm::vec3 sun = dayStateAt(kNoon, rotation).toSun;
    const float offZenith = glm::degrees(std::acos(std::clamp(sun.y, -1.0f, 1.0f)));
    EXPECT_NEAR(offZenith, std::abs(rotation), 1e-3f) << rotation;
    EXPECT_NEAR(sun.x, 0.0f, 1e-6f) << rotation;           // tilted about the east-west axis only
    EXPECT_EQ(sun.z < 0.0f, rotation < 0.0f) << rotation;  // documented: negative tilts towards -z
  }
  // The east and west horizon points lie on the tilt axis and do not move.
  expectNear(dayStateAt(0, -40.0f).toSun, {1, 0, 0}, 1e-6f);
  expectNear(dayStateAt(kSunset, -40.0f).toSun, {-1, 0, 0}, 1e-6f);
}

TEST(DayCycle, MoonIsOppositeAndDirectionsAreUnit) {
  for (const float rotation : {-90.0f, -30.0f, 0.0f, 17.0f, 90.0f}) {
    for (std::int64_t t = 0; t <= kTicksPerDay; t += 37) {
      const DayState d = dayStateAt(t, rotation);
      EXPECT_EQ(d.toMoon, -d.toSun) << t;
      EXPECT_NEAR(glm::length(d.toSun), 1.0f, 1e-6f) << t;
      EXPECT_EQ(d.sunIsShadowLight, d.toSun.y >= 0.0f) << t;
      EXPECT_EQ(d.toShadowLight, d.sunIsShadowLight ? d.toSun : d.toMoon) << t;
    }
  }
}

TEST(DayCycle, ShadowLightSwitchesAtTheHorizonInTheDark) {
  for (const float rotation : {0.0f, -30.0f}) {
    EXPECT_TRUE(dayStateAt(kSunset - 1, rotation).sunIsShadowLight);
    EXPECT_FALSE(dayStateAt(kSunset + 1, rotation).sunIsShadowLight);
    EXPECT_FALSE(dayStateAt(kTicksPerDay - 1, rotation).sunIsShadowLight);
    EXPECT_TRUE(dayStateAt(kTicksPerDay + 1, rotation).sunIsShadowLight);
    for (const std::int64_t centre : {kSunset, kTicksPerDay}) {
      for (std::int64_t t = centre - 3; t <= centre + 3; ++t) {
        const DayState d = dayStateAt(t, rotation);
        EXPECT_LT(glm::length(d.lightColor), 1e-3f) << t;
        EXPECT_LT(d.directStrength, 1e-3f) << t;
      }
    }
  }
}

TEST(DayCycle, SunAndMoonLightStrengths) {
  const DayState noon = dayStateAt(kNoon, 0.0f);
  EXPECT_FLOAT_EQ(noon.directStrength, 1.0f);
  EXPECT_NEAR(noon.lightColor.r, 3.0f, 0.3f);
  EXPECT_GT(noon.lightColor.r, noon.lightColor.b);  // warm
  const DayState midnight = dayStateAt(kMidnight, 0.0f);
  EXPECT_FLOAT_EQ(midnight.directStrength, 1.0f);
  EXPECT_NEAR(glm::length(midnight.lightColor), 0.5f, 0.25f);
  EXPECT_GT(midnight.lightColor.b, midnight.lightColor.r);      // bluish
  EXPECT_EQ(dayStateAt(kNoon + 1, 0.0f).directStrength, 1.0f);  // a few degrees fade, not a whole-day ramp
  EXPECT_EQ(dayStateAt(500, 0.0f).directStrength, 1.0f);
}

// No pop anywhere: the light and the sky change only a little from one tick to the next.
TEST(DayCycle, EverythingIsContinuousTickToTick) {
  for (const float rotation : {0.0f, -30.0f, 45.0f, 89.0f}) {
    DayState previous = dayStateAt(-1, rotation);
    float light = 0.0f, sky = 0.0f, scalars = 0.0f;
    for (std::int64_t t = 0; t <= kTicksPerDay + 1; ++t) {
      const DayState d = dayStateAt(t, rotation);
      light = std::max(light, biggestChange(d.lightColor, previous.lightColor));
      sky = std::max({sky, biggestChange(d.skyZenith, previous.skyZenith),
                      biggestChange(d.skyHorizon, previous.skyHorizon),
                      biggestChange(d.fogColor, previous.fogColor),
                      biggestChange(d.sunColor, previous.sunColor)});
      scalars = std::max({scalars, std::abs(d.directStrength - previous.directStrength),
                          std::abs(d.skyBrightness - previous.skyBrightness),
                          std::abs(d.starVisibility - previous.starVisibility)});
      previous = d;
    }
    EXPECT_LT(light, 0.05f) << rotation;
    EXPECT_LT(sky, 0.01f) << rotation;
    EXPECT_LT(scalars, 0.01f) << rotation;
  }
}

TEST(DayCycle, HugeTicksNeitherDriftNorJump) {
  for (const std::int64_t base : {kHuge, kHuge * 1000, kMaxTicks - kTicksPerDay - 1}) {
    expectSame(dayStateAt(base, -30.0f), dayStateAt(base + kTicksPerDay, -30.0f));
    expectSame(dayStateAt(base, -30.0f), dayStateAt(base % kTicksPerDay, -30.0f));
    const float step = glm::length(dayStateAt(base + 1, -30.0f).toSun - dayStateAt(base, -30.0f).toSun);
    EXPECT_GT(step, 0.0f) << base;
    EXPECT_LT(step, 1e-3f) << base;  // one tick is 0.015 degrees
  }
  expectSame(dayStateAt(kMaxTicks, 10.0f), dayStateAt(kMaxTicks % kTicksPerDay, 10.0f));
}

TEST(DayCycle, FiniteAndInRangeForAnyTickAndRotation) {
  std::vector<std::int64_t> ticks = {0,     1,     5999,  6000,  6001,      11999,         12000,    12001,
                                     18000, 23999, 24000, kHuge, kHuge + 1, kMaxTicks - 1, kMaxTicks};
  for (std::int64_t t = 0; t < kTicksPerDay; t += 97) ticks.push_back(t);
  std::vector<float> rotations = {-90.0f, -89.999f, 89.999f, 90.0f, -0.0f};
  for (float r = -90.0f; r <= 90.0f; r += 7.5f) rotations.push_back(r);
  for (const float rotation : rotations) {
    for (const std::int64_t t : ticks) {
      const DayState d = dayStateAt(t, rotation);
      ASSERT_TRUE(allFinite(d)) << t << " " << rotation;
      EXPECT_NEAR(glm::length(d.toShadowLight), 1.0f, 1e-6f) << t << " " << rotation;
      EXPECT_GE(d.dayFraction, 0.0);
      EXPECT_LT(d.dayFraction, 1.0);
      EXPECT_TRUE(d.directStrength >= 0.0f && d.directStrength <= 1.0f);
      EXPECT_TRUE(d.starVisibility >= 0.0f && d.starVisibility <= 1.0f);
      EXPECT_TRUE(d.skyBrightness >= kNightSkyBrightness && d.skyBrightness <= 1.0f);
      const Lightmap map = buildLightmap(d, t);
      for (const glm::vec3& texel : map.texels) ASSERT_TRUE(finite(texel)) << t << " " << rotation;
    }
  }
}

TEST(DayCycle, SkyColoursThroughTheDay) {
  const DayState noon = dayStateAt(kNoon, 0.0f);
  const DayState sunset = dayStateAt(kSunset, 0.0f);
  const DayState midnight = dayStateAt(kMidnight, 0.0f);
  EXPECT_GT(noon.skyZenith.b, noon.skyZenith.r);  // blue day
  EXPECT_GT(noon.skyHorizon.b, noon.skyHorizon.r);
  EXPECT_GT(sunset.skyHorizon.r, 2.0f * sunset.skyHorizon.b);  // orange-red horizon
  EXPECT_GT(dayStateAt(0, 0.0f).skyHorizon.r, 2.0f * dayStateAt(0, 0.0f).skyHorizon.b);
  EXPECT_LT(glm::length(midnight.skyZenith), 0.05f);  // near-black blue night
  EXPECT_GT(midnight.skyZenith.b, midnight.skyZenith.r);
  EXPECT_GT(glm::length(noon.fogColor), 5.0f * glm::length(midnight.fogColor));
  // The sun disc reddens near the horizon.
  const glm::vec3 lowSun = dayStateAt(100, 0.0f).sunColor;
  EXPECT_LT(lowSun.g / lowSun.r, 0.6f * noon.sunColor.g / noon.sunColor.r);
  EXPECT_EQ(noon.starVisibility, 0.0f);
  EXPECT_EQ(midnight.starVisibility, 1.0f);
  EXPECT_FLOAT_EQ(noon.skyBrightness, 1.0f);
  EXPECT_FLOAT_EQ(midnight.skyBrightness, kNightSkyBrightness);
}

TEST(Lightmap, VanillaBrightnessCurve) {
  EXPECT_EQ(lightLevelBrightness(0), 0.0f);
  EXPECT_EQ(lightLevelBrightness(15), 1.0f);
  EXPECT_NEAR(lightLevelBrightness(5), (1.0f / 3.0f) / (4.0f - 1.0f), 1e-6f);
  for (int level = 1; level <= 15; ++level)
    EXPECT_GT(lightLevelBrightness(level), lightLevelBrightness(level - 1));
  EXPECT_EQ(lightLevelBrightness(-3), 0.0f);
  EXPECT_EQ(lightLevelBrightness(99), 1.0f);
}

void expectMonotonic(const Lightmap& map) {
  for (int s = 0; s < Lightmap::kSize; ++s) {
    for (int b = 0; b < Lightmap::kSize; ++b) {
      const glm::vec3 here = map.at(b, s);
      const glm::vec3 left = map.at(std::max(b - 1, 0), s), below = map.at(b, std::max(s - 1, 0));
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(here, left))) << b << " " << s;
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(here, below))) << b << " " << s;
      EXPECT_TRUE(glm::all(glm::lessThanEqual(here, glm::vec3(1.0f)))) << b << " " << s;
    }
  }
}

TEST(Lightmap, MonotonicInBothLevels) {
  expectMonotonic(buildLightmap(dayStateAt(kNoon, 0.0f), kNoon));
  expectMonotonic(buildLightmap(dayStateAt(kMidnight, 0.0f), kMidnight));
  const Lightmap noon = buildLightmap(dayStateAt(kNoon, 0.0f), kNoon);
  EXPECT_LT(noon.at(0, 0).g, noon.at(0, 8).g);  // strictly brighter somewhere, not flat
  EXPECT_LT(noon.at(0, 0).g, noon.at(8, 0).g);
  EXPECT_TRUE(glm::all(glm::greaterThan(noon.at(0, 0), glm::vec3(0.0f))));
  EXPECT_TRUE(glm::all(glm::lessThan(noon.at(0, 0), glm::vec3(0.05f))));  // near black
  EXPECT_EQ(noon.at(0, 15), glm::vec3(1.0f));
}

TEST(Lightmap, NightSkyIsDarkAndBluish) {
  const glm::vec3 day = buildLightmap(dayStateAt(kNoon, 0.0f), kNoon).at(0, 15);
  const glm::vec3 night = buildLightmap(dayStateAt(kMidnight, 0.0f), kMidnight).at(0, 15);
  EXPECT_NEAR(day.g, 1.0f, 0.01f);
  EXPECT_NEAR(night.g, 0.2f, 0.05f);
  EXPECT_GT(night.b, night.r);
}

TEST(Lightmap, BlockLightIsWarm) {
  const glm::vec3 torch = buildLightmap(dayStateAt(kMidnight, 0.0f), kMidnight).at(15, 0);
  EXPECT_GT(torch.r, torch.g);
  EXPECT_GT(torch.g, torch.b);
  EXPECT_GT(torch.r, 0.9f);
}

TEST(Lightmap, FlickerIsDeterministicAndGentle) {
  const DayState night = dayStateAt(kMidnight, 0.0f);
  // Blue: the red channel of a full torch is clamped at 1 and would hide the flicker.
  float low = 1.0f, high = 0.0f, biggestStep = 0.0f;
  float previous = buildLightmap(night, kHuge - 1).at(15, 0).b;
  for (std::int64_t t = kHuge; t < kHuge + 2000; ++t) {
    const Lightmap map = buildLightmap(night, t);
    EXPECT_EQ(map.texels, buildLightmap(night, t).texels);
    const float b = map.at(15, 0).b;
    low = std::min(low, b);
    high = std::max(high, b);
    biggestStep = std::max(biggestStep, std::abs(b - previous));
    previous = b;
  }
  EXPECT_LT(low / high, 0.99f);           // it does flicker
  EXPECT_GT(low / high, 0.94f);           // by a few percent
  EXPECT_LT(biggestStep / high, 0.025f);  // smoothly
  EXPECT_EQ(buildLightmap(night, kMaxTicks).texels, buildLightmap(night, kMaxTicks).texels);
}

TEST(Lightmap, AtReadsTheDocumentedLayout) {
  const Lightmap map = buildLightmap(dayStateAt(kMidnight, 0.0f), 0);
  EXPECT_EQ(map.at(3, 7), map.texels[7 * Lightmap::kSize + 3]);
  EXPECT_EQ(map.at(-1, 99), map.at(0, 15));
}

}  // namespace
}  // namespace terrasol
