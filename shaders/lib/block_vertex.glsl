// The mesher's 16-byte vertex (engine/mesh/mesh_data.h, PackedVertex), unpacked. Its fields' shifts
// and masks (BV_<field>_SHIFT, BV_<field>_MASK) and scales are injected from there.

struct BlockVertex {
  vec3 position;  // blocks, from the section's minimum corner
  int texture;
  int face;       // 0..5 Direction, 6..9 cross planes: indexes FACE_NORMALS / FACE_TANGENTS / FACE_UPS
  int tint;       // Tint id (core/tint.h): TINT_NONE, TINT_WATER, ...
  vec3 tintColour;  // sRGB 0..1: what a tinted vertex's texture is multiplied by (lib/block_tint.glsl)
  float blockLight, skyLight;  // 0..1
  float ao;                    // 0..1 (0 = darkest corner)
  vec2 uv;                     // textures across (0..1, or up to 16 on a merged quad), v = 0 at the top row
  bool merged;                 // QuadRole::Merged (mesh/face_merge.h)
};

uint bitField(uint word, uint shift, uint mask) { return (word >> shift) & mask; }

BlockVertex unpackBlockVertex(uvec4 p) {
  BlockVertex v;
  v.position = vec3(bitField(p.x, BV_X_SHIFT, BV_X_MASK), bitField(p.x, BV_Y_SHIFT, BV_Y_MASK),
                    bitField(p.x, BV_Z_SHIFT, BV_Z_MASK)) / BV_POSITION_STEPS;
  v.texture = int(bitField(p.y, BV_TEXTURE_SHIFT, BV_TEXTURE_MASK));
  v.face = int(bitField(p.y, BV_FACE_SHIFT, BV_FACE_MASK));
  v.tint = int(bitField(p.y, BV_TINT_SHIFT, BV_TINT_MASK));
  v.merged = bitField(p.y, BV_ROLE_SHIFT, BV_ROLE_MASK) == QUAD_ROLE_MERGED;
  // Light sums over the ao + 1 cells around the corner (PackedVertex::light).
  uint ao = bitField(p.z, BV_AO_SHIFT, BV_AO_MASK);
  float cells = float(ao + 1u) * BV_CELL_LIGHT;
  v.blockLight = float(bitField(p.z, BV_BLOCK_LIGHT_SHIFT, BV_BLOCK_LIGHT_MASK)) / cells;
  v.skyLight = float(bitField(p.z, BV_SKY_LIGHT_SHIFT, BV_SKY_LIGHT_MASK)) / cells;
  v.ao = float(ao) / float(BV_AO_MASK);
  v.tintColour = vec3(bitField(p.z, BV_TINT_RED_SHIFT, BV_TINT_RED_MASK),
                      bitField(p.z, BV_TINT_GREEN_SHIFT, BV_TINT_GREEN_MASK),
                      bitField(p.w, BV_TINT_BLUE_SHIFT, BV_TINT_BLUE_MASK)) /
                 vec3(BV_TINT_RED_MASK, BV_TINT_GREEN_MASK, BV_TINT_BLUE_MASK);
  v.uv = vec2(bitField(p.w, BV_U_SHIFT, BV_U_MASK), bitField(p.w, BV_V_SHIFT, BV_V_MASK)) / BV_UV_STEPS;
  return v;
}
