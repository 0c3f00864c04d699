#include "shaderpack/pack_macros.h"

#include <string>

namespace terrasol {

std::vector<ShaderDefine> packMacros() {
  std::vector<ShaderDefine> defines{
      {"MC_VERSION", std::to_string(kPackMcVersion)},
      {"MC_GL_VERSION", std::to_string(kPackGlVersion)},
      {"MC_GLSL_VERSION", std::to_string(kPackGlVersion)},
      {"MC_OS_LINUX", "1"},
      {"MC_GL_VENDOR_OTHER", "1"},
      {"MC_GL_RENDERER_OTHER", "1"},
      {"MC_RENDER_QUALITY", "1.0"},
      {"MC_SHADOW_QUALITY", "1.0"},
      {"MC_HAND_DEPTH", "0.125"},
      {"MC_NORMAL_MAP", "1"},
      {"MC_SPECULAR_MAP", "1"},
      {"MC_TEXTURE_FORMAT_LAB_PBR", "1"},
      {"MC_TEXTURE_FORMAT_LAB_PBR_1_3", "1"},
  };
  constexpr const char* kStages[] = {"NONE",
                                     "SKY",
                                     "SUNSET",
                                     "CUSTOM_SKY",
                                     "SUN",
                                     "MOON",
                                     "STARS",
                                     "VOID",
                                     "TERRAIN_SOLID",
                                     "TERRAIN_CUTOUT_MIPPED",
                                     "TERRAIN_CUTOUT",
                                     "ENTITIES",
                                     "BLOCK_ENTITIES",
                                     "DESTROY",
                                     "OUTLINE",
                                     "DEBUG",
                                     "HAND_SOLID",
                                     "TERRAIN_TRANSLUCENT",
                                     "TRIPWIRE",
                                     "PARTICLES",
                                     "CLOUDS",
                                     "RAIN_SNOW",
                                     "WORLD_BORDER",
                                     "HAND_TRANSLUCENT"};
  for (int i = 0; i < static_cast<int>(std::size(kStages)); ++i)
    defines.push_back({std::string("MC_RENDER_STAGE_") + kStages[i], std::to_string(i)});
  return defines;
}

}  // namespace terrasol
