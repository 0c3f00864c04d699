// The mesher's 16-byte vertex (engine/mesh/mesh_data.h, PackedVertex), unpacked.

struct BlockVertex {
  vec3 position;  // blocks, from the section's minimum corner
  int texture;
  int face;       // 0..5 Direction, 6..9 cross planes: indexes FACE_NORMALS / FACE_TANGENTS / FACE_UPS
  int tint;       // Tint: TINT_GRASS, ... (lib/block_tint.glsl)
  vec2 tintClimate;  // temperature, downfall: 0..1 along the colormaps' axes
  float blockLight, skyLight;  // 0..1
  float ao;                    // 0..1 (0 = darkest corner)
  vec2 uv;                     // textures across (0..1, or up to 16 on a merged quad), v = 0 at the top row
  bool merged;                 // QuadRole::Merged (mesh/face_merge.h)
};

BlockVertex unpackBlockVertex(uvec4 p) {
  BlockVertex v;
  v.position = vec3(p.x & 1023u, (p.x >> 10) & 1023u, (p.x >> 20) & 1023u) / 32.0;
  v.texture = int(p.y & 0xFFFFu);
  v.face = int((p.y >> 16) & 15u);
  v.tint = int((p.y >> 20) & 7u);
  v.merged = ((p.y >> 23) & 3u) == 2u;
  // Light sums over the ao + 1 cells around the corner (PackedVertex::light).
  uint ao = (p.z >> 12) & 3u;
  float cells = float(ao + 1u) * 15.0;
  v.blockLight = float(p.z & 63u) / cells;
  v.skyLight = float((p.z >> 6) & 63u) / cells;
  v.ao = float(ao) / 3.0;
  v.tintClimate = vec2((p.z >> 14) & 255u, (p.z >> 22) & 255u) / 255.0;
  v.uv = vec2(p.w & 511u, (p.w >> 9) & 511u) / 16.0;
  return v;
}
