#pragma once
// The render presets, from "low" for slow machines to "ultra": each a documented set of the settings
// that cost the most (docs/rendering.md, Presets), leaving every other setting as it was. Scenes take
// one as render.preset (their own keys then change it further), the game's menu applies one, and the
// first start picks one from its probe. Plain C++.

#include <array>
#include <optional>

#include "core/render_settings.h"

namespace terrasol {

enum class RenderPreset { Low, Medium, High, Ultra };
inline constexpr EnumNames<RenderPreset, 4> kRenderPresets{{"low", "medium", "high", "ultra"}};

struct PresetSettings {
  int viewDistance;  // chunks
  int shadowResolution;
  float shadowDistance;  // blocks
  int pcfSamples;
  bool reflections;
  float reflectionScale;
  int reflectionSteps;
  Antialiasing antialiasing;
  bool bloom;
  CloudMode clouds;
  float fogDensity;  // height fog at its base (0: none)
  bool shafts;
  int lodDistance;  // chunks of far terrain (0: none)
  float lodDetail;  // its tiles split while nearer than this times their width
};

// Low keeps shadows (they are the look) and leaves out the rest: a slow llvmpipe machine's; medium adds
// view distance, FXAA and flat clouds (fancy ones cost llvmpipe some 25 ms a frame at 1280x720); high
// and ultra are a GPU's, with fancy clouds and a light haze the sun's shafts show in.
inline constexpr float kPresetHaze = 0.004f;
inline constexpr std::array<PresetSettings, 4> kPresetSettings{{
    {3, 1024, 64.0f, 1, false, 0.25f, 12, Antialiasing::None, false, CloudMode::Off, 0.0f, false, 32, 0.75f},
    {4, 1024, 64.0f, 1, false, 0.25f, 12, Antialiasing::Fxaa, false, CloudMode::Flat, 0.0f, false, 48, 1.0f},
    {8, 2048, 96.0f, 1, true, 0.25f, 12, Antialiasing::Taa, true, CloudMode::Fancy, kPresetHaze, true, 128,
     2.0f},
    {12, 4096, 128.0f, 2, true, 0.5f, 24, Antialiasing::Taa, true, CloudMode::Fancy, kPresetHaze, true, 256,
     2.0f},
}};

inline const PresetSettings& presetSettings(RenderPreset preset) {
  return kPresetSettings[static_cast<std::size_t>(preset)];
}

// `Settings`: anything with the members a preset decides (a scene, the game's settings): viewDistance,
// shadow, reflections, antialiasing, bloom, clouds, fog, shafts and lod.

// The preset the settings match, if any (the menu shows "custom" otherwise).
template <class Settings>
std::optional<RenderPreset> presetOf(const Settings& s) {
  for (std::size_t i = 0; i < kPresetSettings.size(); ++i) {
    const PresetSettings& p = kPresetSettings[i];
    if (s.viewDistance == p.viewDistance && s.shadow.enabled && s.shadow.resolution == p.shadowResolution &&
        s.shadow.distance == p.shadowDistance && s.shadow.pcfSamples == p.pcfSamples &&
        s.reflections.enabled == p.reflections && s.reflections.resolutionScale == p.reflectionScale &&
        s.reflections.maxSteps == p.reflectionSteps && s.antialiasing == p.antialiasing &&
        s.bloom.enabled == p.bloom && s.clouds.mode == p.clouds && s.fog.density == p.fogDensity &&
        s.shafts.enabled == p.shafts && s.lod.distance == p.lodDistance && s.lod.detail == p.lodDetail)
      return static_cast<RenderPreset>(i);
  }
  return std::nullopt;
}

// Sets what the preset decides; everything else (the shadow map's warp, its update frames, the fog's
// base ...) stays.
template <class Settings>
void applyPreset(RenderPreset preset, Settings& s) {
  const PresetSettings& p = presetSettings(preset);
  s.viewDistance = p.viewDistance;
  s.shadow.enabled = true;
  s.shadow.resolution = p.shadowResolution;
  s.shadow.distance = p.shadowDistance;
  s.shadow.pcfSamples = p.pcfSamples;
  s.reflections.enabled = p.reflections;
  s.reflections.resolutionScale = p.reflectionScale;
  s.reflections.maxSteps = p.reflectionSteps;
  s.antialiasing = p.antialiasing;
  s.bloom.enabled = p.bloom;
  s.clouds.mode = p.clouds;
  s.fog.density = p.fogDensity;
  s.shafts.enabled = p.shafts;
  s.lod.distance = p.lodDistance;
  s.lod.detail = p.lodDetail;
}

}  // namespace terrasol
