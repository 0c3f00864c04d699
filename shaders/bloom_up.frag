#version 450 core
// Bloom's way back up: this level plus the weighted sum of the levels below it, scaled up bilinearly.

#include "lib/bilinear.glsl"

layout(binding = 0) uniform sampler2D u_level;  // this level, linear HDR
layout(binding = 1) uniform sampler2D u_below;  // the levels below summed, half this size

uniform float u_spread;  // the weight of each level below relative to the one above it

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  vec3 here = texelFetch(u_level, ivec2(gl_FragCoord.xy), 0).rgb;
  o_color = vec4(here + u_spread * bilinearTexels(u_below, gl_FragCoord.xy * 0.5 - 0.5), 1.0);
}
