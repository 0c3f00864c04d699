// The render presets (core/render_preset.h): each costs no less than the one below it, a scene's own
// keys change what render.preset set, and settings are recognised as the preset they match.

#include "core/render_preset.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/scene_file.h"

namespace terrasol {
namespace {

TEST(RenderPreset, EachAsksNoLessThanTheOneBelow) {
  for (std::size_t i = 1; i < kPresetSettings.size(); ++i) {
    const PresetSettings& lower = kPresetSettings[i - 1];
    const PresetSettings& p = kPresetSettings[i];
    EXPECT_GE(p.viewDistance, lower.viewDistance) << i;
    EXPECT_GE(p.shadowResolution, lower.shadowResolution) << i;
    EXPECT_GE(p.shadowDistance, lower.shadowDistance) << i;
    EXPECT_GE(p.pcfSamples, lower.pcfSamples) << i;
    EXPECT_GE(p.reflections, lower.reflections) << i;
    EXPECT_GE(static_cast<int>(p.antialiasing), static_cast<int>(lower.antialiasing)) << i;
    EXPECT_GE(p.bloom, lower.bloom) << i;
    EXPECT_GE(static_cast<int>(p.clouds), static_cast<int>(lower.clouds)) << i;
    EXPECT_GE(p.fogDensity, lower.fogDensity) << i;
    EXPECT_GE(p.shafts, lower.shafts) << i;
  }
}

TEST(RenderPreset, ASceneKeyChangesWhatThePresetSet) {
  const SceneFile scene = parseScene(
      R"({"world": {"generator": "flat"}, "camera": {"position": [0, 70, 0], "look_at": [1, 70, 0]},
          "render": {"view_distance": 2, "preset": "high", "bloom": {"enabled": false}}})",
      "preset.json");
  EXPECT_EQ(scene.viewDistance, 2) << "the scene's own key, whatever the order";
  EXPECT_EQ(scene.shadow.resolution, 2048);
  EXPECT_EQ(scene.antialiasing, Antialiasing::Taa);
  EXPECT_FALSE(scene.bloom.enabled);
  EXPECT_EQ(scene.clouds.mode, CloudMode::Fancy);
  EXPECT_TRUE(scene.shafts.enabled);
  EXPECT_GT(scene.fog.density, 0.0f);
  EXPECT_THROW(parseScene(R"({"world": {"generator": "flat"}, "render": {"preset": "potato"}})", "p.json"),
               Error);
}

TEST(RenderPreset, SettingsAreKnownByThePresetTheyMatch) {
  for (const RenderPreset preset :
       {RenderPreset::Low, RenderPreset::Medium, RenderPreset::High, RenderPreset::Ultra}) {
    SceneFile s;
    applyPreset(preset, s);
    EXPECT_EQ(presetOf(s), preset) << kRenderPresets.nameOf(preset);
    s.clouds.mode = s.clouds.mode == CloudMode::Fancy ? CloudMode::Off : CloudMode::Fancy;
    EXPECT_EQ(presetOf(s), std::nullopt) << "custom";
    applyPreset(preset, s);
    s.shafts.enabled = !s.shafts.enabled;
    EXPECT_EQ(presetOf(s), std::nullopt) << "custom";
    applyPreset(preset, s);
    ++s.viewDistance;
    EXPECT_EQ(presetOf(s), std::nullopt) << "custom";
  }
}

}  // namespace
}  // namespace terrasol
