// A reflection marched at a lower resolution, filtered up with regard to depth: of the four nearest
// marched texels, each weighs by its bilinear weight and by how close its surface lies to this
// pixel's, so a reflection neither bleeds across an edge nor onto another surface. Returns the
// filtered colour and, in w, the largest closeness (1: a texel on this very surface; near 0: none).
// `uv`: the pixel's screen position; `depth`: its distance along the view.

vec4 upsampledReflection(sampler2D colour, sampler2D hits, vec2 uv, float depth) {
  ivec2 size = textureSize(colour, 0);
  vec2 at = uv * vec2(size) - 0.5;
  ivec2 base = ivec2(floor(at));
  vec2 f = at - vec2(base);
  // The four texels' depths (hits.w; -1: not marched) in textureGather's order: (0,1), (1,1), (1,0), (0,0).
  vec4 depths = textureGather(hits, uv, 3);
  vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  vec4 marched = vec4(greaterThanEqual(depths, vec4(0.0)));
  vec4 near = marched / (1.0 + abs(depths - depth) / (0.02 * depth + 0.05));
  vec4 w = marched * (bilinear * near + 1e-6);
  const ivec2 offsets[4] = ivec2[4](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0));
  vec3 sum = vec3(0.0);
  for (int k = 0; k < 4; ++k) sum += texelFetch(colour, clamp(base + offsets[k], ivec2(0), size - 1), 0).rgb * w[k];
  float weights = dot(w, vec4(1.0));
  return vec4(weights > 0.0 ? sum / weights : vec3(0.0), max(max(near.x, near.y), max(near.z, near.w)));
}
