#version 450 core
// Adds the reflections (reflection.frag, at its own resolution) to the lit scene, filtered up with
// regard to depth: of the four nearest marched texels, each weighs by its bilinear weight and by how
// close its surface lies to this pixel's, so a reflection neither bleeds across an edge nor onto a
// surface too rough to reflect (added only where this pixel itself is smooth enough). Drawn at depth
// 1 against the scene's depth with GL_GREATER: only where something was drawn.

#include "lib/screen_position.glsl"

layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;
layout(binding = UNIT_REFLECTION) uniform sampler2D u_reflection;
layout(binding = UNIT_REFLECTION_HITS) uniform sampler2D u_hits;  // w: the marched surface's distance

uniform float u_minSmoothness;

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(g_specular, pixel, 0).r < u_minSmoothness) {
    o_color = vec4(0.0);
    return;
  }
  float distance = length(unproject(v_ndc, texelFetch(g_depth, pixel, 0).r));
  ivec2 size = textureSize(u_reflection, 0);
  vec2 at = (v_ndc * 0.5 + 0.5) * vec2(size) - 0.5;
  ivec2 base = ivec2(floor(at));
  vec2 f = at - vec2(base);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 texel = clamp(base + o, ivec2(0), size - 1);
    vec4 hit = texelFetch(u_hits, texel, 0);
    if (hit.z < 0.0) continue;  // not marched: rough, or sky
    float bilinear = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    float near = 1.0 / (1.0 + abs(hit.w - distance) / (0.02 * distance + 0.05));
    float w = bilinear * near + 1e-6;
    sum += texelFetch(u_reflection, texel, 0).rgb * w;
    weights += w;
  }
  o_color = vec4(weights > 0.0 ? sum / weights : vec3(0.0), 0.0);  // blended: rgb added, alpha kept
}
