#include "frame_report.h"

#include <random>

#include "scene_render/shadow_truth.h"

namespace terrasol {

nlohmann::json shadowReport(SceneRenderer& renderer, int index, const RenderedFrame& frame,
                            const FrameRequest& request) {
  const float distance = renderer.scene().shadow.distance;
  const ShadowError error = measureShadowError(renderer.world(), frame.pixels, frame.geometry, distance);
  if (frame.geometry.shadowTexelWorld <= 0.0f) {
    // A shader pack places its own map: there is no offset to move it by, so no flicker is measured.
    nlohmann::json out = shadowErrorJson(error, 0.0, 0);
    out["flicker_pct"] = nullptr;
    return out;
  }
  std::mt19937 random(static_cast<std::uint32_t>(index) * 2654435761u + 1u);
  std::uniform_real_distribution<double> within(-0.5, 0.5);
  FrameRequest moved = request;
  moved.timed = false;
  moved.readBack = true;
  moved.aside = true;
  const double texel = frame.geometry.shadowTexelWorld;
  moved.shadowCentreOffset =
      glm::dvec3(within(random) * texel, within(random) * texel, within(random) * texel);
  const RenderedFrame again = renderer.renderFrame(index, moved);
  std::size_t compared = 0;
  const double flicker = flickerPercent(frame.pixels, again.pixels, frame.geometry, distance, compared);
  return shadowErrorJson(error, flicker, compared);
}

nlohmann::json frameReport(int index, const RenderedFrame& frame) {
  nlohmann::json ms = nlohmann::json::object();
  double total = 0.0;
  for (const PassTiming& t : frame.timings) {
    ms[t.pass] = t.ms;
    total += t.ms;
  }
  ms["total"] = total;
  nlohmann::json skipped = nlohmann::json::array();
  for (const auto& s : frame.stats.passesSkipped) skipped.push_back({{"pass", s.pass}, {"why", s.why}});
  return {{"frame", index},
          {"ms", ms},
          {"nan_pixels", frame.nanPixels},
          {"chunks",
           {{"drawn", frame.stats.sectionsDrawn},
            {"culled", frame.stats.sectionsCulled},
            {"hidden", frame.stats.sectionsHidden},
            {"shadow_casters", frame.stats.shadowCasters},
            {"shadow_casters_hidden", frame.stats.shadowCastersHidden},
            {"shadow_casters_off_view", frame.stats.shadowCastersOffView}}},
          {"quads", {{"drawn", frame.stats.quadsDrawn}, {"facing_away", frame.stats.quadsFacingAway}}},
          {"props",
           {{"drawn", frame.stats.propsDrawn},
            {"culled", frame.stats.propsCulled},
            {"shadow_casters", frame.stats.propShadowCasters}}},
          {"lod_tiles", {{"drawn", frame.stats.lodTilesDrawn}, {"culled", frame.stats.lodTilesCulled}}},
          {"lod_triangles_drawn", frame.stats.lodTrianglesDrawn},
          {"lod_shadow_casters", frame.stats.lodShadowCasters},
          {"passes_skipped", skipped}};
}

LodError lodReport(SceneRenderer& truth, int index, const RenderedFrame& frame, const SceneFile& scene) {
  FrameRequest exact;
  exact.readBack = true;
  const RenderedFrame drawn = truth.renderFrame(index, exact);
  FrameRequest half;
  half.renderScale = 0.5f;
  const Image halfImage = truth.renderFrame(index, half).image;
  return measureLodError(frame, drawn, scene.viewDistance * double(kChunkSize),
                         scene.lod.distance * double(kChunkSize), &halfImage);
}

}  // namespace terrasol
