#pragma once
// What --benchmark prints from its frame times: frames per second at the median frame, over the
// slowest 1 % of frames (their mean time: "1 % low", as frame-time tools report it), and on average.

#include <vector>

namespace terrasol {

struct FrameRateSummary {
  std::size_t frames = 0;
  double seconds = 0.0;
  double medianFps = 0.0, onePercentLowFps = 0.0, meanFps = 0.0;
  double medianMs = 0.0, onePercentLowMs = 0.0;
};

// `frameSeconds`: each frame's wall time. Empty input gives all zeros.
FrameRateSummary summarizeFrames(std::vector<double> frameSeconds);

}  // namespace terrasol
