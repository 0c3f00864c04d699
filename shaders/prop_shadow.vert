#version 450 core
// Shadow pass for props: their vertices into the warped light-space depth map, as blocks'.

#include "lib/shadow_warp.glsl"

layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_UV) in vec2 a_uv;

uniform mat4 u_shadowMatrix;  // camera-relative world -> light clip space (unwarped)
uniform vec3 u_modelOffset;   // the model's origin minus the camera position
uniform mat3 u_basis;

out vec2 v_uv;

void main() {
  vec4 p = u_shadowMatrix * vec4(u_modelOffset + u_basis * a_position, 1.0);
  p.xy = warpShadow(p.xy);
  gl_Position = p;
  v_uv = a_uv;
}
