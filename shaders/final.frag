#version 450 core
// Final pass: exposure, filmic tone map, then sRGB encoding of the scene (debug views and block icons
// encode their own). At a render scale this draws at the scene's size, and upscale.frag takes it to
// the target's. With SHARPEN (after TAA, whose history blurs a little) it first sharpens the image.

#include "lib/color.glsl"
#include "lib/compressed_range.glsl"

layout(binding = 0) uniform sampler2D u_scene;  // linear HDR
uniform float u_exposure;

layout(location = OUT_COLOR) out vec4 o_color;

// Narkowicz's fit of the ACES film curve: [0, inf) -> [0, 1).
vec3 tonemapAces(vec3 x) {
  x = max(x, vec3(0.0));
  return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

#ifdef SHARPEN
const float kSharpen = 0.1;


// An unsharp mask over the four neighbours in a compressed range, kept within their span so an edge
// gains no halo.
vec3 sharpened(ivec2 p) {
  ivec2 last = textureSize(u_scene, 0) - 1;
  vec3 c = compress(max(texelFetch(u_scene, p, 0).rgb, vec3(0.0)));
  vec3 n = compress(max(texelFetch(u_scene, clamp(p + ivec2(0, 1), ivec2(0), last), 0).rgb, vec3(0.0)));
  vec3 s = compress(max(texelFetch(u_scene, clamp(p - ivec2(0, 1), ivec2(0), last), 0).rgb, vec3(0.0)));
  vec3 e = compress(max(texelFetch(u_scene, clamp(p + ivec2(1, 0), ivec2(0), last), 0).rgb, vec3(0.0)));
  vec3 w = compress(max(texelFetch(u_scene, clamp(p - ivec2(1, 0), ivec2(0), last), 0).rgb, vec3(0.0)));
  vec3 lo = min(c, min(min(n, s), min(e, w))), hi = max(c, max(max(n, s), max(e, w)));
  return expand(clamp(c + kSharpen * (4.0 * c - n - s - e - w), lo, hi));
}
#endif

void main() {
#ifdef SHARPEN
  vec3 hdr = sharpened(ivec2(gl_FragCoord.xy));
#else
  vec3 hdr = texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb;
#endif
  o_color = vec4(linearToSrgb(tonemapAces(hdr * u_exposure)), 1.0);
}
