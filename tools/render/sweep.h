#pragma once
// terrasol-render --sweep: every combination of the swept scene values rendered and measured against
// ray-traced truth, written as DIR/sweep.csv and plotted as DIR/sweep.png with the Pareto front marked:
// shadow error against shadow + lighting ms; when a render.reflections key is swept, the share of
// reflections disagreeing with the truth against the reflection pass's ms; when render.antialiasing or
// render.scale is, the frame's mean error against its 3 x 3 supersampled truth against the frame's ms
// (but the shadow map's); when a render.lod key is, far terrain's error against full detail out to the
// scene's far edge (lod/, scene_render/lod_error.h) against the far terrain pass's ms.

#include <filesystem>
#include <string>
#include <vector>

namespace terrasol {

struct Sweep {
  std::string key;                  // e.g. "render.shadow.resolution"
  std::vector<std::string> values;  // e.g. {"512", "1024"}
};

// "KEY=V1,V2,..." -> Sweep; throws Error when malformed.
Sweep parseSweep(const std::string& text);

// Renders frame 0 of `scene` for every combination (applied after `overrides`), prints a line per
// combination, writes `out`/sweep.csv and `out`/sweep.png. Returns the number of combinations.
int runSweep(const std::filesystem::path& scene, const std::vector<std::string>& overrides,
             const std::vector<Sweep>& sweeps, const std::filesystem::path& out);

}  // namespace terrasol
