#version 450 core
// Shadow pass: depth only; with CUTOUT, texels the G-buffer pass discards cast no shadow either. With
// TRANSLUCENT, the colour light keeps through the surface: white where clear, its own colour where
// opaque (a coloured filter, like water's blue).

#include "lib/atlas_sample.glsl"

layout(binding = UNIT_ATLAS_ALBEDO) uniform sampler2D u_atlasAlbedo;

in vec3 v_tint;  // linear

#ifdef TRANSLUCENT
layout(location = OUT_COLOR) out vec4 o_transmittance;
#endif

void main() {
  vec4 albedo = atlasTexel(u_atlasAlbedo, atlasCoord());
#ifdef CUTOUT
  if (albedo.a < 0.5) discard;
#endif
#ifdef TRANSLUCENT
  // Alpha: the depth below which the colour applies (lib/shadow.glsl), clamped like the depth test.
  o_transmittance = vec4(mix(vec3(1.0), albedo.rgb * v_tint, albedo.a), clamp(gl_FragCoord.z, 0.0, 1.0));
#endif
}
