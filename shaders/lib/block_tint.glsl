// A block vertex's tint (engine/core/tint.h), linear: grass and foliage from the packs' colormaps at
// the vertex's tint climate, water by temperature, Minecraft's fixed birch and spruce leaf colours.
// sRGB colormap textures, so the sampler returns linear colour.

#include "lib/color.glsl"

layout(binding = UNIT_GRASS_COLORMAP) uniform sampler2D u_grassColormap;
layout(binding = UNIT_FOLIAGE_COLORMAP) uniform sampler2D u_foliageColormap;

// The colormap at (1 - temperature, 1 - downfall), between texel centres as tintColour() reads it.
vec3 colormapTint(sampler2D map, vec2 climate) {
  vec2 size = vec2(textureSize(map, 0));
  vec2 texel = (1.0 - climate) * (size - 1.0) + 0.5;
  return textureLod(map, texel / size, 0.0).rgb;
}

vec3 waterTint(float temperature) {
  vec3 srgb = temperature < WATER_TEMPERATE_FROM
                  ? mix(WATER_COLD, WATER_TEMPERATE, clamp(temperature / WATER_TEMPERATE_FROM, 0.0, 1.0))
                  : mix(WATER_TEMPERATE, WATER_WARM,
                        clamp((temperature - WATER_TEMPERATE_TO) / (1.0 - WATER_TEMPERATE_TO), 0.0, 1.0));
  return srgbToLinear(srgb);
}

vec3 blockTint(BlockVertex v) {
  switch (v.tint) {
    case TINT_GRASS: return colormapTint(u_grassColormap, v.tintClimate);
    case TINT_FOLIAGE: return colormapTint(u_foliageColormap, v.tintClimate);
    case TINT_WATER: return waterTint(v.tintClimate.x);
    case TINT_BIRCH: return srgbToLinear(BIRCH_FOLIAGE);
    case TINT_SPRUCE: return srgbToLinear(SPRUCE_FOLIAGE);
    default: return vec3(1.0);
  }
}
