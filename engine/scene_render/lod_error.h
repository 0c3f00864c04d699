#pragma once
// Far terrain's error against full detail (render.lod): the same frame drawn with full detail out to
// the far edge, slow and exact, compared pixel by pixel in the band far terrain draws: pixels whose
// surface lies beyond the full-detail distance in either picture, or that show sky in one and ground in
// the other. As a yardstick, the truth drawn at half the resolution against itself in the same band.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>

#include "scene_render/scene_render.h"

namespace terrasol {

struct LodError {
  std::size_t band = 0;          // pixels compared
  double mean = 0.0, p99 = 0.0;  // per-pixel difference, the largest of the three channels, 0..1
  // Far terrain shows sky where the truth has ground, under ground of its own and between two pixels of
  // one surface (lod_error.cpp, crack): sky through the terrain, not a skyline drawn a little lower;
  // nearer than 0.9 of the far edge, where the fog leaves half the surface to see.
  std::size_t holes = 0;
  // Sky in one picture and ground in the other (nearer than 0.9 of the far edge), silhouettes included.
  std::size_t skyDiffers = 0;
  std::optional<double> halfResolutionMean, halfResolutionP99;
};

// `lod` and `truth` with their G-buffers read back (FrameRequest::readBack), of one size; `fullDetail`:
// the blocks out to which both draw full detail; `farEdge`: far terrain's distance in blocks;
// `halfResolution`: the truth drawn at half scale.
LodError measureLodError(const RenderedFrame& lod, const RenderedFrame& truth, double fullDetail,
                         double farEdge, const Image* halfResolution = nullptr);

nlohmann::json lodErrorJson(const LodError& e);

}  // namespace terrasol
