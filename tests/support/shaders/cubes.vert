#version 450 core
// Test scene: solid-coloured boxes, positions already in world space.

layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_NORMAL) in vec3 a_normal;
layout(location = ATTRIB_COLOR) in vec3 a_color;

uniform mat4 u_viewProjection;

out vec3 v_normal;
out vec3 v_color;

void main() {
  v_normal = a_normal;
  v_color = a_color;
  gl_Position = u_viewProjection * vec4(a_position, 1.0);
}
