#pragma once
// Uniforms that several passes' programs share, one table per shader library: the light and lightmap
// (lib/lighting.glsl), the sky and fog (lib/sky.glsl), the shadow lookup (lib/shadow.glsl) and its
// warp (lib/shadow_warp.glsl), the reflected rays' march (lib/ssr.glsl) and water's waves
// (lib/waves.glsl). Each is built from a program that includes the library (render/gl/uniforms.h).

#include "render/frame.h"
#include "render/gl/uniforms.h"

namespace terrasol {

// Cascades are never warped.
struct WarpUniforms {
  WarpUniforms() = default;
  explicit WarpUniforms(const LinkedProgram& p);
  void set(const ShadowSettings& settings) const;

  gl::Uniform<int> warp;
  gl::Uniform<float> strength;
};

struct ShadowUniforms {
  ShadowUniforms() = default;
  explicit ShadowUniforms(const LinkedProgram& p);
  // `live`: the map shows this frame's light (else the lookup is lit everywhere).
  void set(const ShadowLookup& shadow, bool live) const;

  WarpUniforms warp;
  gl::Uniform<int> cascades;
  gl::Uniform<glm::mat4> matrices;
  gl::Uniform<float> texelWorlds, depthRanges, resolution, pcfRadius;
  gl::Uniform<bool> pcfRadiusInBlocks, live;
};

// Direct light, ambient tint, lightmap.
struct LightingUniforms {
  LightingUniforms() = default;
  explicit LightingUniforms(const LinkedProgram& p);
  void set(const FrameView& view) const;

  gl::Uniform<glm::vec3> toLight, lightColor, ambientTint;
  gl::Uniform<bool> materialAo;
  gl::Uniform<glm::vec3> lightmapSky, lightmapBlock;
  gl::Uniform<float> lightmapFloor;
};

// The sky and the fog that fades distant surfaces into it (lighting, sky and translucent).
struct SkyUniforms {
  SkyUniforms() = default;
  explicit SkyUniforms(const LinkedProgram& p);
  void set(const FrameView& view) const;

  gl::Uniform<glm::vec3> zenith, horizon, toSun, toMoon, sunColor, moonColor;
  gl::Uniform<float> starVisibility;
  gl::Uniform<glm::vec2> fogRange;
  gl::Uniform<bool> underWater;
  gl::Uniform<float> waterTop;
  gl::Uniform<glm::vec3> waterFog;
  gl::Uniform<glm::vec3> cloudOrigin, cloudLight, cloudToLight;  // lib/clouds.glsl
  gl::Uniform<glm::vec2> cloudNoise;
  gl::Uniform<glm::vec2> heightFog;
  gl::Uniform<glm::vec3> heightFogColour;
};

// The reflected rays' march and the smoothness they fade in from.
struct SsrUniforms {
  SsrUniforms() = default;
  explicit SsrUniforms(const LinkedProgram& p);
  void set(const FrameView& view, const ReflectionSettings& settings) const;

  gl::Uniform<glm::mat4> inverseViewProjection, viewProjection;
  gl::Uniform<glm::vec2> nearFar;
  gl::Uniform<int> maxSteps;
  gl::Uniform<float> thickness, maxDistance, minSmoothness;
};

// Water's waves: their phase in world time and their origin.
struct WaveUniforms {
  WaveUniforms() = default;
  explicit WaveUniforms(const LinkedProgram& p);
  void set(const FrameInputs& inputs) const;

  gl::Uniform<float> time;
  gl::Uniform<glm::vec3> origin;
};

// A lit program that fogs and reads the shadow map: lighting, sky and, with `shadow.settings->enabled`,
// the shadow lookup.
struct LitUniforms {
  LitUniforms() = default;
  explicit LitUniforms(const LinkedProgram& p) : lighting(p), sky(p), shadow(p) {}
  void set(const FrameView& view, const ShadowLookup& lookup) const;

  LightingUniforms lighting;
  SkyUniforms sky;
  ShadowUniforms shadow;
};

}  // namespace terrasol
