#version 450 core
// Adds the reflections (reflection.frag, at its own resolution) to the lit scene, filtered up with
// regard to depth (lib/reflection_upsample.glsl), where this pixel itself is smooth enough. Drawn at
// depth 1 against the scene's depth with GL_GREATER: only where something was drawn.

in vec2 v_ndc;

#include "lib/view_depth.glsl"
#include "lib/reflection_upsample.glsl"

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
  o_color = vec4(upsampledReflection(u_reflection, u_hits, v_ndc * 0.5 + 0.5, depth).rgb, 0.0);  // rgb added, alpha kept
}
