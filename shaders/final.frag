#version 450 core
// Final pass: the scene scaled up to the target when drawn at a render scale, exposure, filmic tone
// map, then sRGB encoding (the only place it happens).

#include "lib/color.glsl"

layout(binding = 0) uniform sampler2D u_scene;  // linear HDR
uniform float u_exposure;
uniform vec2 u_sceneScale;  // scene texels per target pixel: 1, or below 1 at a render scale

layout(location = OUT_COLOR) out vec4 o_color;

// Narkowicz's fit of the ACES film curve: [0, inf) -> [0, 1).
vec3 tonemapAces(vec3 x) {
  x = max(x, vec3(0.0));
  return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Edge-aware upscaling: Catmull-Rom keeps edges sharp where bilinear would blur them; its 4 x 4 taps
// are folded into 5 bilinear reads (the corners' small weights left out, the rest renormalised), and
// clamping to the 2 x 2 nearest texels keeps it from ringing (no halo, no overshoot past an edge).
vec3 upscaled() {
  vec2 size = vec2(textureSize(u_scene, 0));
  vec2 at = gl_FragCoord.xy * u_sceneScale;
  vec2 centre1 = floor(at - 0.5) + 0.5;
  vec2 f = at - centre1;
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 w12 = w1 + w2;
  vec2 at0 = (centre1 - 1.0) / size, at3 = (centre1 + 2.0) / size, at12 = (centre1 + w2 / w12) / size;
  vec3 sum = texture(u_scene, vec2(at12.x, at0.y)).rgb * (w12.x * w0.y) +
             texture(u_scene, vec2(at0.x, at12.y)).rgb * (w0.x * w12.y) +
             texture(u_scene, at12).rgb * (w12.x * w12.y) +
             texture(u_scene, vec2(at3.x, at12.y)).rgb * (w3.x * w12.y) +
             texture(u_scene, vec2(at12.x, at3.y)).rgb * (w12.x * w3.y);
  float weight = w12.x * w0.y + w0.x * w12.y + w12.x * w12.y + w3.x * w12.y + w12.x * w3.y;
  ivec2 last = ivec2(size) - 1, near = ivec2(centre1);  // the texel left of and below the pixel
  vec3 a = texelFetch(u_scene, clamp(near, ivec2(0), last), 0).rgb;
  vec3 b = texelFetch(u_scene, clamp(near + ivec2(1, 0), ivec2(0), last), 0).rgb;
  vec3 c = texelFetch(u_scene, clamp(near + ivec2(0, 1), ivec2(0), last), 0).rgb;
  vec3 d = texelFetch(u_scene, clamp(near + ivec2(1, 1), ivec2(0), last), 0).rgb;
  return clamp(sum / max(weight, 1e-4), min(min(a, b), min(c, d)), max(max(a, b), max(c, d)));
}

void main() {
  vec3 hdr = u_sceneScale == vec2(1.0) ? texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb : upscaled();
  o_color = vec4(linearToSrgb(tonemapAces(hdr * u_exposure)), 1.0);
}
