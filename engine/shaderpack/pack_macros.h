#pragma once
// The macros OptiFine defines after a pack's `#version` (OptiFineDoc shaders.txt "Macros"), as
// Terrasol answers them: Minecraft 1.21.11 (whose block table it carries), OpenGL and GLSL 4.50, Linux,
// full render and shadow quality, normal and specular maps in LabPBR 1.3 (Terrasol's default pack's
// format), and the render stages' numbers for `renderStage`.

#include <vector>

#include "assets/shader_source.h"

namespace terrasol {

inline constexpr int kPackMcVersion = 12111;  // 1.21.11 as MC_VERSION writes versions
inline constexpr int kPackGlVersion = 450;

std::vector<ShaderDefine> packMacros();

// OptiFine's render stages (MC_RENDER_STAGE_*), in its order from 0.
enum class RenderStage {
  None,
  Sky,
  Sunset,
  CustomSky,
  Sun,
  Moon,
  Stars,
  Void,
  TerrainSolid,
  TerrainCutoutMipped,
  TerrainCutout,
  Entities,
  BlockEntities,
  Destroy,
  Outline,
  Debug,
  HandSolid,
  TerrainTranslucent,
  Tripwire,
  Particles,
  Clouds,
  RainSnow,
  WorldBorder,
  HandTranslucent
};

}  // namespace terrasol
