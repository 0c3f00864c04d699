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

// Ghosting: where the truth changed (by more than kGhostChange in a channel) kGhostFrames frames ago
// or earlier and has not changed back, how much of the old colour the frame still shows: its difference
// from the truth projected onto the old truth's, 0 (none) to 1 (all of it). A pixel over kGhostKept
// keeps a colour the scene no longer shows.
struct GhostError {
  double overPct = 0.0;  // of the changed pixels, those over kGhostKept
  double p99 = 0.0;      // of the kept share over the changed pixels
  std::size_t changedPixels = 0;
};
inline constexpr int kGhostFrames = 4;
inline constexpr double kGhostChange = 0.25;
inline constexpr double kGhostKept = 0.1;

// `big` averaged over `factor` x `factor` blocks (its size a multiple of `factor`), in linear light.
Image downsample(const Image& big, int factor);
// `frame` against `truth`, of the same size.
AaError measureAaError(const Image& frame, const Image& truth);
// `frame` against `truth`, where `changed` is the truth kGhostFrames - 1 frames before it and `before`
// the one before that (the change to count came between these two); all of one size.
GhostError measureGhosting(const Image& frame, const Image& truth, const Image& changed, const Image& before);
nlohmann::json aaErrorJson(const AaError& error, int supersample);
nlohmann::json ghostJson(const GhostError& ghost);

}  // namespace terrasol
