#version 450 core
// Far terrain (render/passes/lod_pass.h): one tile's cells, camera-relative (lod/lod_vertex.h). Where
// full detail covers the cell a terrace's vertex follows, the vertex sinks to the world's floor, under
// the ground drawn there. A heightfield's vertex brings its own normal. With SHADOW: into the warped
// shadow map instead.

#include "lib/octahedral.glsl"

layout(location = ATTRIB_LOD_CORNER) in ivec3 a_corner;  // x, z in 1/LOD_XZ_STEPS cell; y in 1/LOD_Y_STEPS block
layout(location = ATTRIB_LOD_CELL) in uvec2 a_cell;      // the cell it follows, + 1; or a normal
layout(location = ATTRIB_LOD_MATERIAL) in uint a_material;

layout(binding = UNIT_LOD_MASK) uniform usampler2D u_fullDetail;  // chunks full detail covers

#ifdef SHADOW
#include "lib/shadow_warp.glsl"
uniform mat4 u_shadowMatrix;  // camera-relative world -> light clip space (unwarped)
#else
uniform mat4 u_viewProjection;  // camera at the origin
#endif
uniform vec3 u_tileOffset;      // the tile's minimum corner (at y 0) minus the camera
uniform int u_cellBlocks;
uniform ivec2 u_maskOffset;  // the tile's minimum corner in blocks from the mask's first chunk
uniform bool u_masked;

const vec3 kFaceNormals[10] = FACE_NORMALS;

out vec3 v_colour;  // sRGB
out vec3 v_normal;
out float v_water;

bool covered(ivec2 cell) {
  ivec2 chunk = (u_maskOffset + cell * u_cellBlocks + u_cellBlocks / 2) >> 4;
  ivec2 size = textureSize(u_fullDetail, 0);
  if (any(lessThan(chunk, ivec2(0))) || any(greaterThanEqual(chunk, size))) return false;
  return texelFetch(u_fullDetail, chunk, 0).r != 0u;
}

void main() {
  float y = float(a_corner.z) / float(LOD_Y_STEPS);
  if (u_masked && covered(ivec2(a_cell) - 1)) y = float(LOD_FLOOR_Y);
  vec3 position = u_tileOffset + vec3(vec2(a_corner.xy * u_cellBlocks) / float(LOD_XZ_STEPS), y).xzy;
  v_colour = vec3(a_material & 255u, (a_material >> 8) & 255u, (a_material >> 16) & 255u) / 255.0;
  uint face = (a_material >> LOD_FACE_SHIFT) & 7u;
  v_normal = face == LOD_FACE_SMOOTH ? octDecode(vec2(a_cell) / 127.5 - 1.0) : kFaceNormals[face];
  v_water = float((a_material >> LOD_WATER_SHIFT) & 1u);
#ifdef SHADOW
  vec4 p = u_shadowMatrix * vec4(position, 1.0);
  p.xy = warpShadow(p.xy);
  gl_Position = p;
#else
  gl_Position = u_viewProjection * vec4(position, 1.0);
#endif
}
