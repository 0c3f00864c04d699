#pragma once
// The sub-pixel offsets temporal anti-aliasing moves the projection by, one per frame: the Halton
// (2, 3) sequence, whose first n points cover the pixel evenly for every n, so a history of any length
// has sampled the whole pixel. Plain C++.

#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>

#include "core/render_scale.h"

namespace terrasol {

// The radical inverse of `index` in `base`: its digits mirrored behind the point, in [0, 1).
inline float halton(int index, int base) {
  float fraction = 1.0f, result = 0.0f;
  for (; index > 0; index /= base) {
    fraction /= static_cast<float>(base);
    result += fraction * static_cast<float>(index % base);
  }
  return result;
}

// How many offsets the sequence cycles through: 8 at full scale, and at a render scale s about 8 / s^2,
// so each output pixel still receives about 8 samples per cycle when the scene is drawn smaller.
inline int jitterPhases(float renderScale) {
  const float s =
      std::isfinite(renderScale) ? std::clamp(renderScale, kMinRenderScale, kMaxRenderScale) : 1.0f;
  return std::clamp(static_cast<int>(std::ceil(8.0f / (s * s))), 8, 64);
}

// Frame `frame`'s offset in scene pixels, in [-0.5, 0.5)^2 (the sequence from its first point, index 0
// being the pixel's corner).
inline glm::vec2 jitterAt(int frame, int phases) {
  const int i = frame % std::max(phases, 1) + 1;
  return {halton(i, 2) - 0.5f, halton(i, 3) - 0.5f};
}

}  // namespace terrasol
