#version 450 core
// Marks the pixels smooth enough to reflect with depth 0, the rest with 1, at the reflection target's
// size, so the march drawn next at depth 1 with GL_GREATER runs only on them: a CPU rasterizer's
// early depth test skips the others block by block, where a branch would still run both sides.

layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;

uniform float u_minSmoothness;
uniform ivec2 u_targetSize;  // this pass's

#include "lib/screen_position.glsl"

void main() {
  ivec2 pixel = pixelUnder(textureSize(g_depth, 0), u_targetSize);
  bool drawn = texelFetch(g_depth, pixel, 0).r < 1.0;
  bool smoothEnough = texelFetch(g_specular, pixel, 0).r >= u_minSmoothness;
  gl_FragDepth = drawn && smoothEnough ? 0.0 : 1.0;
}
