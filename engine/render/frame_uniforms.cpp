#include "render/frame_uniforms.h"

#include <algorithm>

#include "core/luma.h"
#include "render/gl_slots.h"
#include "render/shadow_map.h"

namespace terrasol {

namespace {

// Sky light's colour: the zenith's hue at a fixed brightness (the lightmap carries the brightness).
glm::vec3 ambientTintOf(glm::vec3 zenith) {
  const float luminance = luma(zenith);
  const glm::vec3 hue = luminance > 1e-5f ? zenith / luminance : glm::vec3(1.0f);
  return glm::mix(glm::vec3(1.0f), glm::clamp(hue, 0.0f, 4.0f), 0.4f);
}

}  // namespace

WarpUniforms::WarpUniforms(const LinkedProgram& p)
    : warp(p, "u_shadowWarp"), strength(p, "u_shadowWarpStrength") {}

void WarpUniforms::set(const ShadowSettings& settings) const {
  const bool warped = settings.mode == ShadowMode::Warped;
  warp.set(warped ? static_cast<int>(settings.warp) : static_cast<int>(ShadowWarp::None));
  strength.set(std::clamp(settings.warpStrength, 0.0f, 0.999f));
}

ShadowUniforms::ShadowUniforms(const LinkedProgram& p)
    : warp(p),
      cascades(p, "u_cascades"),
      matrices(p, "u_shadowMatrices"),
      texelWorlds(p, "u_shadowTexelWorlds"),
      depthRanges(p, "u_shadowDepthRanges"),
      resolution(p, "u_shadowResolution"),
      pcfRadius(p, "u_pcfRadius"),
      pcfRadiusInBlocks(p, "u_pcfRadiusInBlocks"),
      live(p, "u_shadowLive") {}

void ShadowUniforms::set(const ShadowLookup& shadow, bool lit) const {
  const ShadowSettings& settings = *shadow.settings;
  warp.set(settings);
  const int layers = shadowLayers(settings);
  std::array<glm::mat4, kMaxShadowCascades> shadowMatrices{};
  std::array<float, kMaxShadowCascades> texels{}, ranges{};
  for (int i = 0; i < layers; ++i) {
    const ShadowView& v = (*shadow.views)[static_cast<std::size_t>(i)];
    shadowMatrices[static_cast<std::size_t>(i)] = v.matrix;
    texels[static_cast<std::size_t>(i)] = v.texelWorld;
    ranges[static_cast<std::size_t>(i)] = v.depthRange;
  }
  cascades.set(layers);
  matrices.set(shadowMatrices.data(), layers);
  texelWorlds.set(texels.data(), layers);
  depthRanges.set(ranges.data(), layers);
  resolution.set(static_cast<float>(settings.resolution));
  pcfRadius.set(std::max(settings.pcfRadius, 0.0f));
  pcfRadiusInBlocks.set(settings.pcfRadiusInBlocks);
  live.set(lit);
  glBindTextureUnit(slots::kUnitShadowMap, shadow.map->depth());
  glBindTextureUnit(slots::kUnitTransmittance, shadow.map->transmittance());
}

LightingUniforms::LightingUniforms(const LinkedProgram& p)
    : toLight(p, "u_toLight"),
      lightColor(p, "u_lightColor"),
      ambientTint(p, "u_ambientTint"),
      materialAo(p, "u_materialAo"),
      lightmapSky(p, "u_lightmapSky"),
      lightmapBlock(p, "u_lightmapBlock"),
      lightmapFloor(p, "u_lightmapFloor") {}

void LightingUniforms::set(const FrameView& view) const {
  const DayState& day = view.day;
  toLight.set(day.toShadowLight);
  lightColor.set(day.lightColor);
  ambientTint.set(ambientTintOf(day.skyZenith));
  materialAo.set(view.materialAo);
  lightmapSky.set(view.lightmap.sky);
  lightmapBlock.set(view.lightmap.block);
  lightmapFloor.set(view.lightmap.floor);
}

void LitUniforms::set(const FrameView& view, const ShadowLookup& lookup) const {
  lighting.set(view);
  if (lookup.settings->enabled) shadow.set(lookup, view.lightUp);
  sky.set(view);
}

SkyUniforms::SkyUniforms(const LinkedProgram& p)
    : zenith(p, "u_skyZenith"),
      horizon(p, "u_skyHorizon"),
      toSun(p, "u_toSun"),
      toMoon(p, "u_toMoon"),
      sunColor(p, "u_sunColor"),
      moonColor(p, "u_moonColor"),
      starVisibility(p, "u_starVisibility"),
      fogRange(p, "u_fogRange"),
      underWater(p, "u_underWater"),
      waterTop(p, "u_waterTop"),
      waterFog(p, "u_waterFog"),
      cloudOrigin(p, "u_cloudOrigin"),
      cloudLight(p, "u_cloudLight"),
      cloudToLight(p, "u_cloudToLight"),
      cloudNoise(p, "u_cloudNoise"),
      heightFog(p, "u_heightFog"),
      heightFogColour(p, "u_heightFogColour") {}

void SkyUniforms::set(const FrameView& view) const {
  const DayState& day = view.day;
  zenith.set(day.skyZenith);
  horizon.set(day.skyHorizon);
  toSun.set(day.toSun);
  toMoon.set(day.toMoon);
  sunColor.set(day.sunColor);
  moonColor.set(day.moonColor);
  starVisibility.set(day.starVisibility);
  fogRange.set(view.fogRange);
  underWater.set(view.underWater);
  waterTop.set(view.waterTop);
  waterFog.set(view.waterFog);
  heightFog.set(view.heightFog);
  heightFogColour.set(view.heightFogColour);
  if (view.clouds) {
    cloudOrigin.set(view.cloudOrigin);
    cloudLight.set(day.lightColor);
    cloudToLight.set(day.toShadowLight);
    // The volumetric march's per-pixel start moves with TAA's jitter (0 without), whose history
    // averages it; a fixed sequence, so a scene's pixels stay the same on every run.
    cloudNoise.set(view.jitter * 37.0f);
    glBindTextureUnit(slots::kUnitClouds, view.clouds);
  }
}

SsrUniforms::SsrUniforms(const LinkedProgram& p)
    : inverseViewProjection(p, "u_inverseViewProjection"),
      viewProjection(p, "u_viewProjection"),
      nearFar(p, "u_nearFar"),
      maxSteps(p, "u_maxSteps"),
      thickness(p, "u_thickness"),
      maxDistance(p, "u_maxDistance"),
      minSmoothness(p, "u_minSmoothness") {}

void SsrUniforms::set(const FrameView& view, const ReflectionSettings& settings) const {
  inverseViewProjection.set(view.inverseViewProjection);
  viewProjection.set(view.viewProjection);
  nearFar.set(view.nearFar);
  maxSteps.set(std::clamp(settings.maxSteps, 1, 256));
  thickness.set(settings.thickness);
  maxDistance.set(settings.maxDistance);
  minSmoothness.set(settings.minSmoothness);
}

// The waves' phase: world time in seconds, wrapped at a whole number of every wave's periods so it
// stays exact after any number of ticks; their origin: the camera's position wrapped at 256 blocks
// (in double), so a far camera sees the same waves as one at the origin.
constexpr std::int64_t kWaveCycleTicks = 20 * 60 * 60;  // an hour

WaveUniforms::WaveUniforms(const LinkedProgram& p) : time(p, "u_waveTime"), origin(p, "u_waveOrigin") {}

void WaveUniforms::set(const FrameInputs& inputs) const {
  const auto ticks = ((inputs.ticks % kWaveCycleTicks) + kWaveCycleTicks) % kWaveCycleTicks;
  time.set(static_cast<float>(ticks) / 20.0f);
  const glm::dvec3 wrapped = glm::mod(inputs.cameraPosition, glm::dvec3(256.0));
  origin.set(glm::vec3(wrapped));
}

}  // namespace terrasol
