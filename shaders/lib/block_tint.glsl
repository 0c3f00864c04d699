// A block vertex's tint, linear: the colour the mesher gave it (core/tint_palette.h: the packs'
// colormaps at its biomes' climate, the biomes' own colours, water's and the fixed leaves'), white
// for untinted vertices.

#include "lib/color.glsl"

vec3 blockTint(BlockVertex v) {
  return v.tint == TINT_NONE ? vec3(1.0) : srgbToLinear(v.tintColour);
}
