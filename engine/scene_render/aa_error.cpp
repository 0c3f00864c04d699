#include "scene_render/aa_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/srgb.h"

namespace terrasol {
namespace {

const std::array<float, 256>& linearOfByte() {
  static const auto table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i)
      t[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<float>(i) / 255.0f);
    return t;
  }();
  return table;
}

double lumaOf(const std::uint8_t* p) {
  return (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
}

}  // namespace

Image downsample(const Image& big, int factor) {
  Image out(big.width / factor, big.height / factor);
  const auto& linear = linearOfByte();
  const float count = static_cast<float>(factor * factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      float sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const std::uint8_t* p = big.pixel(x * factor + dx, y * factor + dy);
          for (int c = 0; c < 3; ++c) sum[c] += linear[p[c]];
          sum[3] += static_cast<float>(p[3]);
        }
      std::uint8_t* o = out.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        o[c] = static_cast<std::uint8_t>(std::lround(linearToSrgb(sum[c] / count) * 255.0f));
      o[3] = static_cast<std::uint8_t>(std::lround(sum[3] / count));
    }
  return out;
}

AaError measureAaError(const Image& frame, const Image& truth) {
  AaError e;
  const int w = std::min(frame.width, truth.width), h = std::min(frame.height, truth.height);
  if (w <= 0 || h <= 0) return e;
  std::vector<double> differences;
  differences.reserve(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  std::size_t edgeOver = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* a = frame.pixel(x, y);
      const std::uint8_t* b = truth.pixel(x, y);
      int most = 0;
      for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a[c]) - int(b[c])));
      const double d = most / 255.0;
      differences.push_back(d);
      double contrast = 0.0;
      const double here = lumaOf(b);
      for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx >= 0 && ny >= 0 && nx < w && ny < h)
          contrast = std::max(contrast, std::abs(lumaOf(truth.pixel(nx, ny)) - here));
      }
      if (contrast > kEdge) {
        ++e.edgePixels;
        edgeOver += d > kOver;
      }
    }
  double sum = 0.0;
  for (double d : differences) sum += d;
  e.mean = sum / static_cast<double>(differences.size());
  const std::size_t at = std::min(differences.size() - 1, differences.size() * 99 / 100);
  std::nth_element(differences.begin(), differences.begin() + static_cast<std::ptrdiff_t>(at),
                   differences.end());
  e.p99 = differences[at];
  e.edgeOverPct =
      e.edgePixels ? 100.0 * static_cast<double>(edgeOver) / static_cast<double>(e.edgePixels) : 0.0;
  return e;
}

GhostError measureGhosting(const Image& frame, const Image& truth, const Image& changed,
                           const Image& before) {
  GhostError g;
  const int w = std::min({frame.width, truth.width, changed.width, before.width});
  const int h = std::min({frame.height, truth.height, changed.height, before.height});
  std::vector<double> kept;
  std::size_t over = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* f = frame.pixel(x, y);
      const std::uint8_t* t = truth.pixel(x, y);
      const std::uint8_t* b = before.pixel(x, y);
      const std::uint8_t* n = changed.pixel(x, y);
      double dot = 0.0, length2 = 0.0;
      int change = 0, changedThen = 0;
      for (int c = 0; c < 3; ++c) {
        const double old = (int(b[c]) - int(t[c])) / 255.0;
        dot += (int(f[c]) - int(t[c])) / 255.0 * old;
        length2 += old * old;
        change = std::max(change, std::abs(int(b[c]) - int(t[c])));
        changedThen = std::max(changedThen, std::abs(int(b[c]) - int(n[c])));
      }
      if (change / 255.0 <= kGhostChange || changedThen / 255.0 <= kGhostChange) continue;
      const double share = std::clamp(dot / length2, 0.0, 1.0);
      kept.push_back(share);
      over += share > kGhostKept;
    }
  g.changedPixels = kept.size();
  if (kept.empty()) return g;
  g.overPct = 100.0 * static_cast<double>(over) / static_cast<double>(kept.size());
  const std::size_t at = std::min(kept.size() - 1, kept.size() * 99 / 100);
  std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(at), kept.end());
  g.p99 = kept[at];
  return g;
}

nlohmann::json ghostJson(const GhostError& ghost) {
  return {{"over_pct", ghost.overPct}, {"p99", ghost.p99}, {"changed_pixels", ghost.changedPixels}};
}

nlohmann::json aaErrorJson(const AaError& error, int supersample) {
  return {{"mean", error.mean},
          {"p99", error.p99},
          {"edge_over_pct", error.edgeOverPct},
          {"edge_pixels", error.edgePixels},
          {"reference_supersample", supersample}};
}

}  // namespace terrasol
