#version 450 core
// Props (engine/render/props.h): a glTF model's vertices placed in the world, camera-relative, each
// with the voxel light where it stands. The G-buffer and translucent passes share it.

layout(location = ATTRIB_POSITION) in vec3 a_position;
layout(location = ATTRIB_NORMAL) in vec3 a_normal;
layout(location = ATTRIB_TANGENT) in vec4 a_tangent;
layout(location = ATTRIB_UV) in vec2 a_uv;
layout(location = ATTRIB_LIGHT) in vec2 a_light;

uniform mat4 u_viewProjection;  // camera at the origin, as for blocks
uniform vec3 u_modelOffset;     // the model's origin minus the camera position (computed in double)
uniform mat3 u_basis;           // model -> world: rotation x uniform scale
uniform mat3 u_rotation;        // for normals and tangents

out vec3 v_position;  // camera-relative
out vec3 v_normal;
out vec4 v_tangent;   // xyz world, w bitangent sign
out vec2 v_uv;
out vec2 v_light;     // block, sky 0..1

void main() {
  v_position = u_modelOffset + u_basis * a_position;
  v_normal = u_rotation * a_normal;
  v_tangent = vec4(u_rotation * a_tangent.xyz, a_tangent.w);
  v_uv = a_uv;
  v_light = a_light;
  gl_Position = u_viewProjection * vec4(v_position, 1.0);
}
