#version 330 compatibility
// The sky, per pixel: the gradient from lib/sky.glsl in the pixel's direction.

#include "/lib/sky.glsl"

uniform mat4 gbufferProjectionInverse;
uniform float viewWidth;
uniform float viewHeight;

/* RENDERTARGETS: 0 */
layout(location = 0) out vec4 color;

void main() {
  vec4 ndc = vec4(gl_FragCoord.xy / vec2(viewWidth, viewHeight) * 2.0 - 1.0, 1.0, 1.0);
  vec4 view = gbufferProjectionInverse * ndc;
  color = vec4(skyAt(normalize(view.xyz / view.w)), 1.0);
}
