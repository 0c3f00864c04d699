#pragma once
// Reflection error against ground truth, as for shadows (shadow_truth.h): from each pixel the
// reflection pass marched, the mirror ray it marched (the same normals, read back from the G-buffer,
// or for water and glass from the pass's own target) is walked through the voxel grid (Amanatides-Woo) to the
// first opaque cube within the pass's max_distance. The screen-space march either found that block, another
// one, or nothing; where it found nothing, the truth's block is either visible on screen (a miss of the
// march) or not (beyond any screen-space method: reported apart).

#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>

#include "render/deferred_renderer.h"
#include "world/world.h"

namespace terrasol {

struct ReflectionCounts {
  std::size_t evaluated = 0;       // marched pixels whose truth is decided
  std::size_t agree = 0;           // the march and the truth hit the same block, or both nothing
  std::size_t wrongHit = 0;        // both hit, different blocks, the truth's more than a pixel away
  std::size_t borderHit = 0;       // both hit, the truth's neighbour across a border within a pixel of
                                   // the hit on screen: the screen cannot tell the two apart there
  std::size_t missedOnScreen = 0;  // the truth's block is visible on screen; the march found nothing
  std::size_t missedOffScreen =
      0;                      // the truth's block is off screen or hidden: no screen-space method sees it
  std::size_t falseHit = 0;   // the truth finds nothing within max_distance; the march hit
  std::size_t ambiguous = 0;  // the truth ray meets a cutout or partial block first (excluded)
};

struct ReflectionError {
  ReflectionCounts total;
  ReflectionCounts opaque, translucent;        // the pass's march from each kind of surface
  std::array<ReflectionCounts, 4> byDistance;  // 0-8, 8-32, 32-64, 64+ blocks from the camera
  std::size_t skyLeakPixels = 0;               // sky light 0, nothing hit, yet light added (a reflected sky)
};

// `surfaceNormals`: the G-buffer keeps mapped normals beside the vertex normals (GBufferContents).
ReflectionError measureReflectionError(const World& world, const GBufferPixels& frame,
                                       const ReflectionPixels& reflections, const FrameGeometry& geometry,
                                       float maxDistance, bool surfaceNormals);

nlohmann::json reflectionErrorJson(const ReflectionError& error);

}  // namespace terrasol
