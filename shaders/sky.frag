#version 450 core
// The sky where nothing was drawn: the depth test runs it only on pixels at depth 1.

#include "lib/sky.glsl"

uniform mat4 u_inverseViewProjection;  // camera-relative

in vec2 v_ndc;
layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  vec4 p = u_inverseViewProjection * vec4(v_ndc, 1.0, 1.0);
  vec3 far = p.xyz / p.w;
  o_color = vec4(skyColor(far / max(length(far), 1e-20)), 1.0);
}
