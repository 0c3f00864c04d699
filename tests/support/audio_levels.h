#pragma once
// How loud interleaved stereo is, channel by channel: the RMS in 16-bit steps, for tests that
// listen to what the audio engine or the game played.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "audio/ogg_file.h"

namespace terrasol::testing {

struct Levels {
  double left = 0.0, right = 0.0;
  double both() const { return (left + right) * 0.5; }
};

inline Levels levels(std::span<const std::int16_t> stereo) {
  Levels l;
  for (std::size_t i = 0; i + 1 < stereo.size(); i += 2) {
    l.left += static_cast<double>(stereo[i]) * stereo[i];
    l.right += static_cast<double>(stereo[i + 1]) * stereo[i + 1];
  }
  const double frames = std::max(1.0, static_cast<double>(stereo.size() / 2));
  return {std::sqrt(l.left / frames), std::sqrt(l.right / frames)};
}

// Of `seconds` of a stereo `wav` from frame `from` (clipped to its end).
inline Levels levels(const Pcm& wav, std::size_t from, double seconds) {
  const std::size_t to = std::min(wav.frames(), from + static_cast<std::size_t>(seconds * wav.rate));
  if (from >= to) return {};
  return levels(std::span(wav.samples).subspan(2 * from, 2 * (to - from)));
}

}  // namespace terrasol::testing
