#version 450 core
// The final image scaled up to the target, at a render scale (the final pass drew it at the scene's
// size, tone mapped and sRGB-encoded: scaling display values, and the costly tone map runs on the
// fewer pixels).

layout(binding = 0) uniform sampler2D u_image;  // sRGB-encoded
uniform vec2 u_sceneScale;  // image texels per target pixel, below 1

layout(location = OUT_COLOR) out vec4 o_color;

// Edge-aware upscaling from the 2 x 2 texels around the pixel: bilinear where they are alike, and
// where they differ (an edge) the blend squeezed into the middle half of the gap between texel
// centres, so edges stay sharp without ringing (every result lies between its four texels).
vec3 upscaled() {
  ivec2 last = textureSize(u_image, 0) - 1;
  vec2 at = gl_FragCoord.xy * u_sceneScale - 0.5;
  ivec2 near = ivec2(floor(at));
  vec2 f = at - vec2(near);
  vec3 a = texelFetch(u_image, clamp(near, ivec2(0), last), 0).rgb;
  vec3 b = texelFetch(u_image, clamp(near + ivec2(1, 0), ivec2(0), last), 0).rgb;
  vec3 c = texelFetch(u_image, clamp(near + ivec2(0, 1), ivec2(0), last), 0).rgb;
  vec3 d = texelFetch(u_image, clamp(near + ivec2(1, 1), ivec2(0), last), 0).rgb;
  vec3 spread = max(max(a, b), max(c, d)) - min(min(a, b), min(c, d));
  float edge = smoothstep(0.04, 0.25, max(spread.r, max(spread.g, spread.b)));
  vec2 g = mix(f, smoothstep(0.25, 0.75, f), edge);
  return mix(mix(a, b, g.x), mix(c, d, g.x), g.y);
}

void main() { o_color = vec4(clamp(upscaled(), 0.0, 1.0), 1.0); }
