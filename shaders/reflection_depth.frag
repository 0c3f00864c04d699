#version 450 core
// The opaque scene's depth at the reflection target's size, so translucent quads behind it are
// depth-tested away before the march from water and glass runs.

layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;

in vec2 v_ndc;

void main() {
  ivec2 size = textureSize(g_depth, 0);
  ivec2 pixel = clamp(ivec2((v_ndc * 0.5 + 0.5) * vec2(size)), ivec2(0), size - 1);
  gl_FragDepth = texelFetch(g_depth, pixel, 0).r;
}
