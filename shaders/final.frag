#version 450 core
// Final pass: exposure, filmic tone map, then sRGB encoding of the scene (debug views and block icons
// encode their own). At a render scale this draws at the scene's size, and upscale.frag takes it to
// the target's.

#include "lib/color.glsl"

layout(binding = 0) uniform sampler2D u_scene;  // linear HDR
uniform float u_exposure;

layout(location = OUT_COLOR) out vec4 o_color;

// Narkowicz's fit of the ACES film curve: [0, inf) -> [0, 1).
vec3 tonemapAces(vec3 x) {
  x = max(x, vec3(0.0));
  return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
  vec3 hdr = texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb;
  o_color = vec4(linearToSrgb(tonemapAces(hdr * u_exposure)), 1.0);
}
