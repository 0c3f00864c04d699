#version 450 core
// Far terrain (render/passes/lod_pass.h): one tile's cells, camera-relative. Where full detail covers
// the cell a vertex follows, the vertex sinks to the world's floor, under the ground drawn there.

layout(location = ATTRIB_LOD_CORNER) in ivec3 a_corner;  // x, z in cells; y in 1/LOD_Y_STEPS block
layout(location = ATTRIB_LOD_CELL) in uvec2 a_cell;      // the cell it follows, + 1
layout(location = ATTRIB_LOD_MATERIAL) in uint a_material;

layout(binding = UNIT_LOD_MASK) uniform usampler2D u_fullDetail;  // chunks full detail covers

uniform mat4 u_viewProjection;  // camera at the origin
uniform vec3 u_tileOffset;      // the tile's minimum corner (at y 0) minus the camera
uniform int u_cellBlocks;
uniform ivec2 u_maskOffset;  // the tile's minimum corner in blocks from the mask's first chunk
uniform bool u_masked;

const vec3 kFaceNormals[10] = FACE_NORMALS;

flat out vec3 v_colour;  // sRGB
flat out vec3 v_normal;
flat out float v_water;

bool covered(ivec2 cell) {
  ivec2 chunk = (u_maskOffset + cell * u_cellBlocks + u_cellBlocks / 2) >> 4;
  ivec2 size = textureSize(u_fullDetail, 0);
  if (any(lessThan(chunk, ivec2(0))) || any(greaterThanEqual(chunk, size))) return false;
  return texelFetch(u_fullDetail, chunk, 0).r != 0u;
}

void main() {
  float y = float(a_corner.z) / float(LOD_Y_STEPS);
  if (u_masked && covered(ivec2(a_cell) - 1)) y = float(LOD_FLOOR_Y);
  vec3 position = u_tileOffset + vec3(float(a_corner.x * u_cellBlocks), y, float(a_corner.y * u_cellBlocks));
  v_colour = vec3(a_material & 255u, (a_material >> 8) & 255u, (a_material >> 16) & 255u) / 255.0;
  v_normal = kFaceNormals[(a_material >> LOD_FACE_SHIFT) & 7u];
  v_water = float((a_material >> LOD_WATER_SHIFT) & 1u);
  gl_Position = u_viewProjection * vec4(position, 1.0);
}
