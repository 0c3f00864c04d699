#version 450 core
// Bloom into the scene: the levels' weighted mean, scaled up from half the scene's size, at `u_strength`; the
// blend keeps (1 - strength) of the scene, so the frame's light is moved, not added.

#include "lib/bilinear.glsl"

layout(binding = 0) uniform sampler2D u_bloom;  // every level summed, half the scene's size
uniform float u_strength;
uniform float u_weights;  // the levels' weights summed

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  vec3 bloom = bilinearTexels(u_bloom, gl_FragCoord.xy * 0.5 - 0.5) / u_weights;
  o_color = vec4(bloom * u_strength, u_strength);
}
