// Where a block vertex's texture is in the atlas this frame (animations move it between tiles).

uniform ivec3 u_atlasGrid;  // columns, slot size, tile size (texels)
uniform vec2 u_atlasSize;   // texels

layout(std430, binding = STORAGE_TILES) readonly buffer Tiles {
  uint tiles[];  // atlas tile shown this frame by each texture id
};

// The top left corner of the tile `texture` shows this frame, in atlas UV (lib/atlas_sample.glsl
// adds the UV within the tile per fragment).
vec2 atlasTile(int texture) {
  int tile = int(tiles[texture]);
  vec2 corner = vec2(tile % u_atlasGrid.x, tile / u_atlasGrid.x) * float(u_atlasGrid.y) + 0.5 * float(u_atlasGrid.z);
  return corner / u_atlasSize;
}
