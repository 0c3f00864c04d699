#pragma once
// The lightmap: (block light level, sky light level) -> linear RGB multiplier for a surface,
// clamp(floor + sky * B(sky level) + block * B(block level), 0, 1) with vanilla's brightness curve B.
// The colours change with the time of day; the 16x16 table of whole levels is the reference the
// tests check, and the lighting shader evaluates the same sum at the pixel's smooth levels
// (shaders/lib/lighting.glsl, lightmapAt; tests/gl/glsl_reference_test.cpp checks the two agree).
// Pure math, no GL.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "core/day_cycle.h"
#include "core/light_level.h"

namespace terrasol {

struct Lightmap {
  static constexpr int kSize = kLightLevels;
  // Linear RGB in [0, 1], index sky * kSize + block (texture x = block level, y = sky level).
  std::array<glm::vec3, kSize * kSize> texels;

  // Levels outside 0..15 are clamped.
  glm::vec3 at(int block, int sky) const;
};

// Vanilla brightness curve per level: f / (4 - 3f), f = level / 15. 0 -> 0, 15 -> 1; levels are clamped.
float lightLevelBrightness(int level);

// The lightmap's terms at one moment: what a level of 15 of each channel adds, and the floor.
struct LightmapColours {
  glm::vec3 sky;    // sky light: the day's brightness, tinted blue towards night
  glm::vec3 block;  // block light: warm, dimmed by the flicker
  float floor;      // what even a sealed cave gets
};

// `ticks` also drives the block light flicker: a gentle few-percent dimming, the same for the same tick
// so renders are reproducible.
LightmapColours lightmapColours(const DayState& day, std::int64_t ticks);

Lightmap buildLightmap(const DayState& day, std::int64_t ticks);

}  // namespace terrasol
