#pragma once
// The 16x16 lightmap: (block light level, sky light level) -> linear RGB multiplier for a surface.
// Rebuilt each frame from the time of day and uploaded as a small texture; pure math, no GL.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "core/day_cycle.h"

namespace terrasol {

struct Lightmap {
  static constexpr int kSize = 16;
  // Linear RGB in [0, 1], index sky * kSize + block (texture x = block level, y = sky level).
  std::array<glm::vec3, kSize * kSize> texels;

  // Levels outside 0..15 are clamped.
  glm::vec3 at(int block, int sky) const;
};

// Vanilla brightness curve per level: f / (4 - 3f), f = level / 15. 0 -> 0, 15 -> 1; levels are clamped.
float lightLevelBrightness(int level);

// `ticks` also drives the block light flicker: a gentle few-percent dimming, the same for the same tick
// so renders are reproducible.
Lightmap buildLightmap(const DayState& day, std::int64_t ticks);

}  // namespace terrasol
