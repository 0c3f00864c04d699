#version 450 core
// G-buffer pass (and translucent pass): block vertices of one section, camera-relative.

#include "lib/atlas_uv.glsl"
#include "lib/block_vertex.glsl"

layout(location = ATTRIB_PACKED) in uvec4 a_packed;

uniform mat4 u_viewProjection;  // camera at the origin: positions stay small far from the world's origin
uniform vec3 u_sectionOffset;   // section's minimum corner minus the camera position (computed in double)
uniform vec3 u_tints[4];        // linear; index 0 is white

out vec3 v_position;  // camera-relative
out vec2 v_uv;
out vec3 v_tint;
out vec3 v_light;     // block, sky, ao
flat out int v_face;

void main() {
  BlockVertex v = unpackBlockVertex(a_packed);
  v_position = u_sectionOffset + v.position;
  v_uv = atlasUv(v.texture, v.uv);
  v_tint = u_tints[v.tint];
  v_light = vec3(v.blockLight, v.skyLight, v.ao);
  v_face = v.face;
  gl_Position = u_viewProjection * vec4(v_position, 1.0);
}
