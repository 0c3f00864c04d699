#version 450 core
// Minecraft's crack (destroy_stage_N) over whatever surface the G-buffer holds inside the dug block's
// cell, laid on by the surface's facing as Minecraft lays it on each face. Blended 2 x crack x stored
// albedo (Minecraft's DST_COLOR, SRC_COLOR): the stored albedo is its square root
// (lib/gbuffer_albedo.glsl), near the sRGB Minecraft blends in, so the crack's sRGB texels go in as is.

#include "lib/color.glsl"
#include "lib/octahedral.glsl"
#include "lib/unproject.glsl"

layout(binding = 0) uniform sampler2D u_depth;
layout(binding = 1) uniform sampler2D u_normals;
layout(binding = 2) uniform sampler2D u_atlas;  // albedo, sRGB
uniform vec3 u_cellMin, u_cellMax;              // camera-relative
uniform vec4 u_tile;                            // the stage's texels in the atlas: u0, v0, u1, v1
uniform vec2 u_viewport;                        // G-buffer pixels

out vec4 o_albedo;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(u_depth, pixel, 0).r;
  if (depth >= 1.0) discard;  // sky
  vec3 p = unproject(gl_FragCoord.xy / u_viewport * 2.0 - 1.0, depth);
  vec4 normals = texelFetch(u_normals, pixel, 0);
#ifdef NO_NORMAL_MAPS
  vec3 n = octDecode(normals.xy);
#else
  vec3 n = octDecode(normals.zw);  // the vertex normal: the face, not its normal map
#endif
  // A step into the surface decides whose it is: the dug block's own face on the cell's side is in,
  // the neighbour's face it stands on (the ground under a fence post) is out, whatever depth's error.
  vec3 inside = p - n * (1.0 / 64.0);
  if (any(lessThan(inside, u_cellMin)) || any(greaterThan(inside, u_cellMax))) discard;
  // Within the cell, 0..1 on each axis; the face's two axes give the texture's, top up on the sides.
  vec3 cell = clamp((p - u_cellMin) / (u_cellMax - u_cellMin), 0.0, 1.0);
  vec3 a = abs(n);
  vec2 uv;
  if (a.x >= a.y && a.x >= a.z) {
    uv = vec2(n.x > 0.0 ? 1.0 - cell.z : cell.z, 1.0 - cell.y);
  } else if (a.y >= a.z) {
    uv = vec2(cell.x, n.y > 0.0 ? cell.z : 1.0 - cell.z);
  } else {
    uv = vec2(n.z > 0.0 ? cell.x : 1.0 - cell.x, 1.0 - cell.y);
  }
  vec4 crack = textureLod(u_atlas, mix(u_tile.xy, u_tile.zw, min(uv, vec2(0.9999))), 0.0);
  if (crack.a < 0.1) discard;  // Minecraft's crumbling shader's test
  o_albedo = vec4(linearToSrgb(crack.rgb), 1.0);
}
