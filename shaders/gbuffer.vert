#version 450 core
// G-buffer pass (and translucent pass): block vertices of one section, camera-relative.

#include "lib/atlas_uv.glsl"
#include "lib/block_vertex.glsl"
#include "lib/block_tint.glsl"

layout(location = ATTRIB_PACKED) in uvec4 a_packed;

uniform mat4 u_viewProjection;  // camera at the origin: positions stay small far from the world's origin
uniform vec3 u_sectionOffset;   // section's minimum corner minus the camera position (computed in double)
uniform vec2 u_viewportPixels;
uniform bool u_sealMergedEdges;  // the G-buffer pass; not the translucent one, whose blending would
                                  // count an overlap twice

const vec3 kFaceNormals[10] = FACE_NORMALS;
const vec3 kFaceTangents[10] = FACE_TANGENTS;
const vec3 kFaceUps[10] = FACE_UPS;

// A merged quad meets smaller faces mid-edge (T-junctions). Their edges are rasterized from different
// vertices, rounded to the subpixel grid apart, and a pixel centre in the sliver between them would
// show the sky through the ground. Moving the quad's corners 1/32 pixel outwards, along the corner's
// diagonal on screen, covers that sliver (at most ~1/180 pixel wide) and nothing a pixel centre would
// notice elsewhere. Left alone behind the near plane, where no direction on screen exists.
vec4 sealed(vec4 clip, vec3 position, BlockVertex v) {
  vec2 side = vec2(v.uv.x > 0.0 ? 1.0 : -1.0, v.uv.y > 0.0 ? -1.0 : 1.0);  // the corner's (u, v) side
  vec3 outward = side.x * kFaceTangents[v.face] + side.y * kFaceUps[v.face];
  vec4 beyond = u_viewProjection * vec4(position + outward, 1.0);
  if (clip.w < 1e-3 || beyond.w < 1e-3) return clip;
  vec2 pixels = (beyond.xy / beyond.w - clip.xy / clip.w) * 0.5 * u_viewportPixels;
  float len = length(pixels);
  if (len < 1e-6) return clip;
  clip.xy += pixels / len * (1.0 / 32.0) * 2.0 / u_viewportPixels * clip.w;
  return clip;
}

out vec3 v_position;  // camera-relative
out vec2 v_uv;
flat out vec2 v_tile;
out vec3 v_tint;  // linear; changes across biome borders
out vec3 v_light;     // block, sky, ao
flat out vec3 v_normal;
flat out vec3 v_tangent;
flat out vec3 v_up;
flat out float v_water;  // 1 on water's quads (tinted as water)

void main() {
  BlockVertex v = unpackBlockVertex(a_packed);
  v_position = u_sectionOffset + v.position;
  v_uv = v.uv;
  v_tile = atlasTile(v.texture);
  v_tint = blockTint(v);
  v_light = vec3(v.blockLight, v.skyLight, v.ao);
  v_normal = kFaceNormals[v.face];
  v_tangent = kFaceTangents[v.face];
  v_up = kFaceUps[v.face];
  v_water = v.tint == TINT_WATER ? 1.0 : 0.0;
  gl_Position = u_viewProjection * vec4(v_position, 1.0);
  if (u_sealMergedEdges && v.merged) gl_Position = sealed(gl_Position, v_position, v);
}
