#version 450 core
// Shadow pass for props: depth only; with CUTOUT (alpha mode MASK) what the G-buffer pass discards
// casts nothing; with TRANSLUCENT (BLEND) the colour the light keeps through the surface, as for glass.

layout(binding = UNIT_PROP_BASE_COLOR) uniform sampler2D u_baseColorMap;
uniform vec4 u_baseColorFactor;
uniform float u_alphaCutoff;

in vec2 v_uv;

#ifdef TRANSLUCENT
layout(location = OUT_COLOR) out vec4 o_transmittance;
#endif

void main() {
#if defined(CUTOUT) || defined(TRANSLUCENT)
  vec4 base = texture(u_baseColorMap, v_uv) * u_baseColorFactor;
#endif
#ifdef CUTOUT
  if (base.a < u_alphaCutoff) discard;
#endif
#ifdef TRANSLUCENT
  o_transmittance = vec4(mix(vec3(1.0), base.rgb, clamp(base.a, 0.0, 1.0)), clamp(gl_FragCoord.z, 0.0, 1.0));
#endif
}
