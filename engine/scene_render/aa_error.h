#pragma once
// A frame's error against its supersampled truth (terrasol-render --reference-supersample N): the
// same frame drawn N x N times larger with no anti-aliasing, averaged down in linear light, compared
// pixel by pixel. An edge pixel is one whose truth differs from a neighbour's by more than kEdge in
// luma; edge_over_pct is the share of those the frame misses by more than kOver.

#include <cstddef>
#include <nlohmann/json.hpp>

#include "assets/image.h"

namespace terrasol {

struct AaError {
  double mean = 0.0;  // per-pixel difference, the largest of the three channels, 0..1
  double p99 = 0.0;
  double edgeOverPct = 0.0;
  std::size_t edgePixels = 0;
};

inline constexpr double kEdge = 0.1;
inline constexpr double kOver = 0.1;

// `big` averaged over `factor` x `factor` blocks (its size a multiple of `factor`), in linear light.
Image downsample(const Image& big, int factor);
// `frame` against `truth`, of the same size.
AaError measureAaError(const Image& frame, const Image& truth);
nlohmann::json aaErrorJson(const AaError& error, int supersample);

}  // namespace terrasol
