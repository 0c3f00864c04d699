#version 450 core
// Inventory icons: the block's albedo, tinted and shaded, as sRGB with straight alpha.

#include "lib/atlas_sample.glsl"
#include "lib/color.glsl"

layout(binding = UNIT_ATLAS_ALBEDO) uniform sampler2D u_atlasAlbedo;  // sRGB: reads linear

uniform bool u_cutout;  // leaves, plants: a texel is there or not

in vec3 v_tint;

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  vec4 albedo = atlasTexel(u_atlasAlbedo, atlasCoord());
  if (u_cutout && albedo.a < 0.5) discard;
  if (albedo.a <= 0.0) discard;
  o_color = vec4(linearToSrgb(albedo.rgb * v_tint), u_cutout ? 1.0 : albedo.a);
}
