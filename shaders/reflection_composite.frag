#version 450 core
// Adds the reflections (reflection.frag, at its own resolution) to the lit scene, filtered up with
// regard to depth: of the four nearest marched texels, each weighs by its bilinear weight and by how
// close its surface lies to this pixel's, so a reflection neither bleeds across an edge nor onto a
// surface too rough to reflect (added only where this pixel itself is smooth enough). Drawn at depth
// 1 against the scene's depth with GL_GREATER: only where something was drawn.

in vec2 v_ndc;

#include "lib/view_depth.glsl"

layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;
layout(binding = UNIT_REFLECTION) uniform sampler2D u_reflection;
layout(binding = UNIT_REFLECTION_HITS) uniform sampler2D u_hits;  // w: the marched surface's depth, or -1

uniform float u_minSmoothness;

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(g_specular, pixel, 0).r < u_minSmoothness) {
    o_color = vec4(0.0);
    return;
  }
  float depth = viewDepth(texelFetch(g_depth, pixel, 0).r);
  ivec2 size = textureSize(u_reflection, 0);
  vec2 uv = v_ndc * 0.5 + 0.5;
  vec2 at = uv * vec2(size) - 0.5;
  ivec2 base = ivec2(floor(at));
  vec2 f = at - vec2(base);
  // The four texels' depths in textureGather's order: (0,1), (1,1), (1,0), (0,0).
  vec4 depths = textureGather(u_hits, uv, 3);
  vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  vec4 near = 1.0 / (1.0 + abs(depths - depth) / (0.02 * depth + 0.05));
  vec4 w = mix(vec4(0.0), bilinear * near + 1e-6, greaterThanEqual(depths, vec4(0.0)));  // -1: not marched
  const ivec2 offsets[4] = ivec2[4](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0));
  vec3 sum = vec3(0.0);
  for (int k = 0; k < 4; ++k) sum += texelFetch(u_reflection, clamp(base + offsets[k], ivec2(0), size - 1), 0).rgb * w[k];
  float weights = dot(w, vec4(1.0));
  o_color = vec4(weights > 0.0 ? sum / weights : vec3(0.0), 0.0);  // blended: rgb added, alpha kept
}
