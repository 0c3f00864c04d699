#include "render/frame_uniforms.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "core/luma.h"
#include "render/gl/uniforms.h"
#include "render/gl_slots.h"
#include "render/shadow_map.h"

namespace terrasol {

using gl::setVec3;

namespace {

// Sky light's colour: the zenith's hue at a fixed brightness (the lightmap carries the brightness).
glm::vec3 ambientTint(glm::vec3 zenith) {
  const float luminance = luma(zenith);
  const glm::vec3 hue = luminance > 1e-5f ? zenith / luminance : glm::vec3(1.0f);
  return glm::mix(glm::vec3(1.0f), glm::clamp(hue, 0.0f, 4.0f), 0.4f);
}

}  // namespace

void setLightingUniforms(GLuint program, const FrameView& view, const ShadowLookup& shadow) {
  const DayState& day = view.day;
  setVec3(program, "u_toLight", day.toShadowLight);
  setVec3(program, "u_lightColor", day.lightColor);
  setVec3(program, "u_ambientTint", ambientTint(day.skyZenith));
  glProgramUniform1i(program, glGetUniformLocation(program, "u_materialAo"), view.materialAo ? 1 : 0);
  setVec3(program, "u_lightmapSky", view.lightmap.sky);
  setVec3(program, "u_lightmapBlock", view.lightmap.block);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_lightmapFloor"), view.lightmap.floor);
  if (shadow.settings->enabled) setShadowUniforms(program, shadow, view.lightUp);
}

void setSkyUniforms(GLuint program, const FrameView& view) {
  const DayState& day = view.day;
  setVec3(program, "u_skyZenith", day.skyZenith);
  setVec3(program, "u_skyHorizon", day.skyHorizon);
  setVec3(program, "u_toSun", day.toSun);
  setVec3(program, "u_toMoon", day.toMoon);
  setVec3(program, "u_sunColor", day.sunColor);
  setVec3(program, "u_moonColor", day.moonColor);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_starVisibility"), day.starVisibility);
  glProgramUniform2fv(program, glGetUniformLocation(program, "u_fogRange"), 1, glm::value_ptr(view.fogRange));
  glProgramUniform1i(program, glGetUniformLocation(program, "u_underWater"), view.underWater ? 1 : 0);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_waterTop"), view.waterTop);
  setVec3(program, "u_waterFog", view.waterFog);
}

void setSsrUniforms(GLuint program, const FrameView& view, const ReflectionSettings& settings) {
  gl::setMat4(program, "u_inverseViewProjection", view.inverseViewProjection);
  gl::setMat4(program, "u_viewProjection", view.viewProjection);
  glProgramUniform2fv(program, glGetUniformLocation(program, "u_nearFar"), 1, glm::value_ptr(view.nearFar));
  glProgramUniform1i(program, glGetUniformLocation(program, "u_maxSteps"),
                     std::clamp(settings.maxSteps, 1, 256));
  glProgramUniform1f(program, glGetUniformLocation(program, "u_thickness"), settings.thickness);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_maxDistance"), settings.maxDistance);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_minSmoothness"), settings.minSmoothness);
}

void setWarpUniforms(GLuint program, const ShadowSettings& settings) {
  const bool warped = settings.mode == ShadowMode::Warped;
  glProgramUniform1i(program, glGetUniformLocation(program, "u_shadowWarp"),
                     warped ? static_cast<int>(settings.warp) : static_cast<int>(ShadowWarp::None));
  glProgramUniform1f(program, glGetUniformLocation(program, "u_shadowWarpStrength"),
                     std::clamp(settings.warpStrength, 0.0f, 0.999f));
}

void setShadowUniforms(GLuint program, const ShadowLookup& shadow, bool live) {
  const ShadowSettings& settings = *shadow.settings;
  setWarpUniforms(program, settings);
  const int layers = shadowLayers(settings);
  std::array<glm::mat4, kMaxShadowCascades> matrices{};
  std::array<float, kMaxShadowCascades> texels{}, ranges{};
  for (int i = 0; i < layers; ++i) {
    const ShadowView& v = (*shadow.views)[static_cast<std::size_t>(i)];
    matrices[static_cast<std::size_t>(i)] = v.matrix;
    texels[static_cast<std::size_t>(i)] = v.texelWorld;
    ranges[static_cast<std::size_t>(i)] = v.depthRange;
  }
  glProgramUniform1i(program, glGetUniformLocation(program, "u_cascades"), layers);
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "u_shadowMatrices"), layers, GL_FALSE,
                            glm::value_ptr(matrices[0]));
  glProgramUniform1fv(program, glGetUniformLocation(program, "u_shadowTexelWorlds"), layers, texels.data());
  glProgramUniform1fv(program, glGetUniformLocation(program, "u_shadowDepthRanges"), layers, ranges.data());
  glProgramUniform1f(program, glGetUniformLocation(program, "u_shadowResolution"),
                     static_cast<float>(settings.resolution));
  glProgramUniform1f(program, glGetUniformLocation(program, "u_pcfRadius"),
                     std::max(settings.pcfRadius, 0.0f));
  glProgramUniform1i(program, glGetUniformLocation(program, "u_pcfRadiusInBlocks"),
                     settings.pcfRadiusInBlocks ? 1 : 0);
  glProgramUniform1i(program, glGetUniformLocation(program, "u_shadowLive"), live ? 1 : 0);
  glBindTextureUnit(slots::kUnitShadowMap, shadow.map->depth());
  glBindTextureUnit(slots::kUnitTransmittance, shadow.map->transmittance());
}

// The waves' phase: world time in seconds, wrapped at a whole number of every wave's periods so it
// stays exact after any number of ticks; their origin: the camera's position wrapped at 256 blocks
// (in double), so a far camera sees the same waves as one at the origin.
constexpr std::int64_t kWaveCycleTicks = 20 * 60 * 60;  // an hour

void setWaveUniforms(GLuint program, const FrameInputs& inputs) {
  const auto ticks = ((inputs.ticks % kWaveCycleTicks) + kWaveCycleTicks) % kWaveCycleTicks;
  glProgramUniform1f(program, glGetUniformLocation(program, "u_waveTime"), static_cast<float>(ticks) / 20.0f);
  const glm::dvec3 wrapped = glm::mod(inputs.cameraPosition, glm::dvec3(256.0));
  gl::setVec3(program, "u_waveOrigin", glm::vec3(wrapped));
}

}  // namespace terrasol
