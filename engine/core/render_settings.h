#pragma once
// The renderer's settings as typed values: what scene files ("render"), the game's settings file and
// terrasol-render's --set give, parsed once at their edge (scene/scene_file.h: parseScene,
// parseShadow) and compared as values. Plain C++.

#include <algorithm>
#include <array>
#include <cstddef>
#include <string_view>

#include "core/enum_names.h"

namespace terrasol {

// Each enum's names in files (scene "render", the game's settings), in the enum's order.
enum class ShadowMode { Warped, Cascaded };
inline constexpr EnumNames<ShadowMode, 2> kShadowModes{{"warped", "cascaded"}};
enum class ShadowWarp { None, Square, Radial };
inline constexpr EnumNames<ShadowWarp, 3> kShadowWarps{{"none", "square", "radial"}};
enum class PcfPattern { Grid, Disk, Tent };
inline constexpr EnumNames<PcfPattern, 3> kPcfPatterns{{"grid", "disk", "tent"}};
inline constexpr EnumNames<bool, 2> kPcfRadiusUnits{{"texels", "blocks"}};  // pcfRadiusInBlocks
inline constexpr int kMaxShadowCascades = 4;

// Specular lobes of the lighting: energy-conserving Blinn-Phong or GGX with Smith visibility.
enum class SpecularModel { BlinnPhong, Ggx };
inline constexpr EnumNames<SpecularModel, 2> kSpecularModels{{"blinn_phong", "ggx"}};

// Anti-aliasing: none, FXAA (a post pass on the display image) or TAA (a jittered projection
// resolved against the reprojected history, which also reconstructs the target's size from a smaller
// scene at a render scale).
enum class Antialiasing { None, Fxaa, Taa };
inline constexpr EnumNames<Antialiasing, 3> kAntialiasingModes{{"none", "fxaa", "taa"}};

// What the debug views show, in this order ("none" = the lit image): G-buffer channels, then the
// reflection pass's hit mask and what it added (black when the pass did not run).
// debug_view.frag gets each value as DEBUG_VIEW_<NAME> (render/shader_defines.cpp).
enum class DebugView {
  None,
  Albedo,
  Normal,
  VertexNormal,
  Specular,
  Lightmap,
  Depth,
  Ao,
  Emission,
  ReflectionHits,
  Reflection
};
inline constexpr EnumNames<DebugView, 11> kDebugViews{{"none", "albedo", "normal", "vertex_normal",
                                                       "specular", "lightmap", "depth", "ao", "emission",
                                                       "reflection_hits", "reflection"}};
inline constexpr bool showsReflections(DebugView v) {
  return v == DebugView::ReflectionHits || v == DebugView::Reflection;
}

// "render.shadow": the shadow map (render/passes/shadow_pass.h draws it, render/shadow_map.h holds it).
struct ShadowSettings {
  bool enabled = true;
  ShadowMode mode = ShadowMode::Warped;
  int cascades = 4;         // cascaded mode: 2..kMaxShadowCascades
  int resolution = 2048;    // texels per side (of each cascade), 16..16384
  float distance = 128.0f;  // blocks from the camera to the map's edge, 1..4096
  ShadowWarp warp = ShadowWarp::Radial;
  float warpStrength = 0.85f;  // [0, 1): 0 = no warp
  int pcfSamples = 1;          // N: (2N + 1)^2 grid taps; above 0 the disk or tent pattern; 0 = one tap
  float pcfRadius = 1.0f;      // texels of the shadow map, or blocks with pcfRadiusInBlocks (0..32)
  bool pcfRadiusInBlocks = false;
  PcfPattern pcfPattern = PcfPattern::Tent;
  float shiftAhead = 0.0f;  // warped mode: the map's centre moves this fraction of `distance` ahead
                            // of the camera (horizontally), as Luanti does: more map where one looks
  int updateFrames = 1;     // with FrameInputs::reuseShadowMap: a changed map is redrawn over this
                            // many frames into a second map (1..16; Luanti's shadow_update_frames)

  bool operator==(const ShadowSettings&) const = default;
};

// "render.reflections": screen-space reflections of smooth surfaces with a sky fallback
// (render/passes/reflection_pass.h). The defaults come from the sweep in docs/performance.md: a
// quarter of the frame's size and 12 steps agree with the ray-traced truth on 98-99 % of the marched
// pixels of the metal and water scenes, for about half the lighting pass's time on llvmpipe.
struct ReflectionSettings {
  bool enabled = true;
  int maxSteps = 12;              // steps along the reflected ray (1..256), then a binary refinement
  float thickness = 1.0f;         // blocks a hit may lie behind the depth buffer's surface (0.01..16)
  float resolutionScale = 0.25f;  // the march runs at this fraction of the frame's size (0.25..1)
  float minSmoothness = 0.6f;     // LabPBR smoothness (0..1) below which no ray is marched
  float maxDistance = 64.0f;      // blocks a ray travels at most (1..1024)

  bool operator==(const ReflectionSettings&) const = default;
};

// "render.water": how water's surface looks.
struct WaterSettings {
  bool waves = true;  // the surface moves with summed waves, deterministic in world time

  bool operator==(const WaterSettings&) const = default;
};

// "render.bloom": light spread from bright pixels, energy-conserving: the frame becomes
// (1 - strength) x itself + strength x its blur, so nothing is added and nothing pops at a threshold.
struct BloomSettings {
  bool enabled = false;
  float strength = 0.04f;  // 0..1: the blur's share of the frame

  bool operator==(const BloomSettings&) const = default;
};

// "render.clouds": Minecraft's cloud layer (core/cloud_layer.h) from the packs' clouds.png, flat texels
// on a plane, fancy 4-block boxes, or volumetric (a thicker slab of density marched and lit by the
// light through it), with their shadows on the ground.
enum class CloudMode { Off, Flat, Fancy, Volumetric };
inline constexpr EnumNames<CloudMode, 4> kCloudModes{{"off", "flat", "fancy", "volumetric"}};
struct CloudSettings {
  CloudMode mode = CloudMode::Off;
  bool shadows = true;  // the sun dims under a cloud (the direct light's shadow term)

  bool operator==(const CloudSettings&) const = default;
};

// "render.fog": height fog, a medium whose density falls off exponentially above a base height; the
// distance fog at the world's edge is separate and always on.
struct FogSettings {
  float density = 0.0f;   // extinction per block at `base` (0..1); 0: no height fog
  float base = 64.0f;     // y of that density (-4096..4096)
  float falloff = 24.0f;  // blocks over which it falls by a factor e (1..1024)

  bool operator==(const FogSettings&) const = default;
};

// "render.shafts": sunlight scattered towards the camera by the height fog's medium wherever the shadow
// map sees the sun: shafts through foliage and cave mouths. Needs shadows and fog.
struct ShaftSettings {
  bool enabled = false;
  int samples = 8;      // along each ray (1..64)
  float scale = 0.25f;  // the march runs at this fraction of the frame's size (0.125..1)

  bool operator==(const ShaftSettings&) const = default;
};

// "render.lod": far terrain beyond the view distance (lod/): tiles of cells that summarise the columns
// they cover, coarser with distance, out to `distance` chunks from the camera.
struct LodSettings {
  int distance = 0;     // chunks to the far edge (0: off; 0..1024); beyond the view distance to matter
  float detail = 1.0f;  // a tile splits while nearer than detail x its width (0.5..8): more, finer tiles
  int minLevel = 2;     // the finest cells, 2^min_level blocks (0..4)
  bool shadows = true;  // it casts into the shadow map

  bool operator==(const LodSettings&) const = default;
};

// The layers the settings ask for: one (warped), or the cascades, smallest first (distance / 2^k).
inline int shadowLayers(const ShadowSettings& settings) {
  return settings.mode == ShadowMode::Cascaded ? std::clamp(settings.cascades, 2, kMaxShadowCascades) : 1;
}
inline float cascadeDistance(const ShadowSettings& settings, int layer) {
  return settings.distance / static_cast<float>(1 << (shadowLayers(settings) - 1 - layer));
}

}  // namespace terrasol
