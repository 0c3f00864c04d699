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
};

// Low keeps shadows (they are the look) and flat clouds, and leaves out the rest: a slow llvmpipe
// machine's; medium adds view distance, FXAA and fancy clouds; high and ultra are a GPU's.
inline constexpr std::array<PresetSettings, 4> kPresetSettings{{
    {3, 1024, 64.0f, 1, false, 0.25f, 12, Antialiasing::None, false, CloudMode::Flat},
    {4, 1024, 64.0f, 1, false, 0.25f, 12, Antialiasing::Fxaa, false, CloudMode::Fancy},
    {8, 2048, 96.0f, 1, true, 0.25f, 12, Antialiasing::Taa, true, CloudMode::Fancy},
    {12, 4096, 128.0f, 2, true, 0.5f, 24, Antialiasing::Taa, true, CloudMode::Fancy},
}};

inline const PresetSettings& presetSettings(RenderPreset preset) {
  return kPresetSettings[static_cast<std::size_t>(preset)];
}

// The preset the settings match, if any (the menu shows "custom" otherwise).
inline std::optional<RenderPreset> presetOf(int viewDistance, const ShadowSettings& shadow,
                                            const ReflectionSettings& reflections, Antialiasing antialiasing,
                                            const BloomSettings& bloom, const CloudSettings& clouds) {
  for (std::size_t i = 0; i < kPresetSettings.size(); ++i) {
    const PresetSettings& p = kPresetSettings[i];
    if (viewDistance == p.viewDistance && shadow.enabled && shadow.resolution == p.shadowResolution &&
        shadow.distance == p.shadowDistance && shadow.pcfSamples == p.pcfSamples &&
        reflections.enabled == p.reflections && reflections.resolutionScale == p.reflectionScale &&
        reflections.maxSteps == p.reflectionSteps && antialiasing == p.antialiasing &&
        bloom.enabled == p.bloom && clouds.mode == p.clouds)
      return static_cast<RenderPreset>(i);
  }
  return std::nullopt;
}

// Sets what the preset decides; everything else (the shadow map's warp, its update frames, ...) stays.
inline void applyPreset(RenderPreset preset, int& viewDistance, ShadowSettings& shadow,
                        ReflectionSettings& reflections, Antialiasing& antialiasing, BloomSettings& bloom,
                        CloudSettings& clouds) {
  const PresetSettings& p = presetSettings(preset);
  viewDistance = p.viewDistance;
  shadow.enabled = true;
  shadow.resolution = p.shadowResolution;
  shadow.distance = p.shadowDistance;
  shadow.pcfSamples = p.pcfSamples;
  reflections.enabled = p.reflections;
  reflections.resolutionScale = p.reflectionScale;
  reflections.maxSteps = p.reflectionSteps;
  antialiasing = p.antialiasing;
  bloom.enabled = p.bloom;
  clouds.mode = p.clouds;
}

}  // namespace terrasol
