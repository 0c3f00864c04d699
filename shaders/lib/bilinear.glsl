// Bilinear filtering from whole-texel fetches (filtered lookups cost far more on llvmpipe): `at` in
// texels, texel centres at whole numbers, edges clamped.

vec3 bilinearTexels(sampler2D image, vec2 at) {
  ivec2 last = textureSize(image, 0) - 1;
  ivec2 i = ivec2(floor(at));
  vec2 f = at - vec2(i);
  vec3 a = texelFetch(image, clamp(i, ivec2(0), last), 0).rgb;
  vec3 b = texelFetch(image, clamp(i + ivec2(1, 0), ivec2(0), last), 0).rgb;
  vec3 c = texelFetch(image, clamp(i + ivec2(0, 1), ivec2(0), last), 0).rgb;
  vec3 d = texelFetch(image, clamp(i + ivec2(1, 1), ivec2(0), last), 0).rgb;
  return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}
