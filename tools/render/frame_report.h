#pragma once
// terrasol-render's per-frame report (--report): the frame's stats, and its measures against the
// truths: shadows and their flicker against the ray-traced shadows, far terrain against full detail.

#include <nlohmann/json.hpp>

#include "scene_render/lod_error.h"
#include "scene_render/scene_render.h"

namespace terrasol {

// Ms per pass, NaN pixels, sections, quads, props, far terrain's tiles and the passes left out.
nlohmann::json frameReport(int index, const RenderedFrame& frame);

// The frame's shadows against ray-traced truth, and their flicker: the same frame again with the shadow
// map placed as if the camera had moved by a random fraction of a texel (the sun frozen, the view kept,
// so every pixel shows the same world point in both). `request` is the frame's own.
nlohmann::json shadowReport(SceneRenderer& renderer, int index, const RenderedFrame& frame,
                            const FrameRequest& request);

// Far terrain's error: frame `index` of `truth` (lodTruthScene of the scene) drawn exactly and at half
// resolution, against `frame`.
LodError lodReport(SceneRenderer& truth, int index, const RenderedFrame& frame, const SceneFile& scene);

}  // namespace terrasol
