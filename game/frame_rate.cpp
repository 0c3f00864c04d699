#include "frame_rate.h"

#include <algorithm>
#include <numeric>

namespace terrasol {

FrameRateSummary summarizeFrames(std::vector<double> frameSeconds) {
  FrameRateSummary s;
  s.frames = frameSeconds.size();
  if (frameSeconds.empty()) return s;
  std::sort(frameSeconds.begin(), frameSeconds.end());
  s.seconds = std::accumulate(frameSeconds.begin(), frameSeconds.end(), 0.0);
  const double median = frameSeconds[frameSeconds.size() / 2];
  const std::size_t slowest = std::max<std::size_t>(1, frameSeconds.size() / 100);
  const double low =
      std::accumulate(frameSeconds.end() - static_cast<std::ptrdiff_t>(slowest), frameSeconds.end(), 0.0) /
      static_cast<double>(slowest);
  s.medianMs = median * 1000.0;
  s.onePercentLowMs = low * 1000.0;
  s.medianFps = median > 0.0 ? 1.0 / median : 0.0;
  s.onePercentLowFps = low > 0.0 ? 1.0 / low : 0.0;
  s.meanFps = s.seconds > 0.0 ? static_cast<double>(s.frames) / s.seconds : 0.0;
  return s;
}

}  // namespace terrasol
