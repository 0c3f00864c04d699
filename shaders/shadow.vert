#version 450 core
// Shadow pass: block vertices into the warped light-space depth map.

#include "lib/atlas_uv.glsl"
#include "lib/block_vertex.glsl"
#include "lib/block_tint.glsl"
#include "lib/shadow_warp.glsl"

layout(location = ATTRIB_PACKED) in uvec4 a_packed;

uniform mat4 u_shadowMatrix;   // camera-relative world -> light clip space (unwarped)
uniform vec3 u_sectionOffset;  // section's minimum corner minus the camera position

out vec2 v_uv;
flat out vec2 v_tile;
out vec3 v_tint;  // linear; changes across biome borders

void main() {
  BlockVertex v = unpackBlockVertex(a_packed);
  vec4 p = u_shadowMatrix * vec4(u_sectionOffset + v.position, 1.0);
  p.xy = warpShadow(p.xy);
  gl_Position = p;
  v_uv = v.uv;
  v_tile = atlasTile(v.texture);
  v_tint = blockTint(v);
}
