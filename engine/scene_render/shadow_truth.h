#pragma once
// Shadow error against ground truth. In a block world exact shadows are cheap: from each visible
// surface point a ray is marched through the voxel grid (Amanatides-Woo) towards the light; the first
// opaque cube it meets shadows the point. The rendered shadow term (the lighting pass's, kept in the HDR
// target's alpha) is then right or wrong, pixel by pixel.

#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>

#include "render/deferred_renderer.h"
#include "world/world.h"

namespace terrasol {

struct ShadowCounts {
  std::size_t evaluated = 0;    // facing the light, within the shadow distance, not ambiguous
  std::size_t falseShadow = 0;  // truth lit, rendered < 0.5
  std::size_t falseLit = 0;     // truth shadowed, rendered >= 0.5
  std::size_t ambiguous = 0;    // rays grazing an edge or crossing cutout or translucent blocks (excluded)
};

struct ShadowError {
  ShadowCounts total;
  std::array<ShadowCounts, 4> byDistance;  // 0-8, 8-32, 32-64, 64+ blocks from the camera
  std::size_t caveLeakPixels = 0;          // sky light 0 but direct light > 0
};

// Every pixel of `frame` facing the light within `distance` blocks of the camera.
ShadowError measureShadowError(const World& world, const GBufferPixels& frame, const FrameGeometry& geometry,
                               float distance);

// Of the pixels of `a` facing the light within 0.9 `distance` (inside the map's edge), the percentage
// whose shadow (rendered term >= 0.5 or not) differs in `b`: the same view, the shadow map placed for a moved
// camera. `compared` gets how many pixels were compared.
double flickerPercent(const GBufferPixels& a, const GBufferPixels& b, const FrameGeometry& geometry,
                      float distance, std::size_t& compared);

nlohmann::json shadowErrorJson(const ShadowError& error, double flickerPct, std::size_t flickerPoints);

}  // namespace terrasol
