#version 330 compatibility
// The shadow pass: every block from the sun (or moon) into the warped map.

#include "/lib/distort.glsl"

out vec2 texcoord;
out vec4 glcolor;

void main() {
  texcoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy;
  glcolor = gl_Color;
  gl_Position = ftransform();
  gl_Position.xyz = distort(gl_Position.xyz);
}
