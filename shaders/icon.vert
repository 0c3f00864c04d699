#version 450 core
// Inventory icons (engine/render/block_icons.h): one block's mesh, isometric, lit from above.

#include "lib/atlas_uv.glsl"
#include "lib/block_vertex.glsl"
#include "lib/block_tint.glsl"

layout(location = ATTRIB_PACKED) in uvec4 a_packed;

uniform mat4 u_transform;  // section blocks -> clip, the block's cell centred in the icon

const vec3 kFaceNormals[10] = FACE_NORMALS;
// Brighter towards the top, darker on the side turned from the light, as Minecraft's inventory
// lights blocks; plants' diagonal planes get the sides' mean.
const vec3 kLight = normalize(vec3(-0.3, 1.0, -0.6));

out vec2 v_uv;
flat out vec2 v_tile;
out vec3 v_tint;  // linear, times the face's shade

void main() {
  BlockVertex v = unpackBlockVertex(a_packed);
  v_uv = v.uv;
  v_tile = atlasTile(v.texture);
  float shade = 0.55 + 0.45 * max(dot(kFaceNormals[v.face], kLight), 0.0);
  v_tint = blockTint(v) * shade;
  gl_Position = u_transform * vec4(v.position, 1.0);
}
