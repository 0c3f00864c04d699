// Where a block vertex's texture is in the atlas this frame (animations move it between tiles).

uniform ivec3 u_atlasGrid;  // columns, slot size, tile size (texels)
uniform vec2 u_atlasSize;   // texels

layout(std430, binding = STORAGE_TILES) readonly buffer Tiles {
  uint tiles[];  // atlas tile shown this frame by each texture id
};

// `uv`: 0..1 across the texture, v = 0 at its top row.
vec2 atlasUv(int texture, vec2 uv) {
  int tile = int(tiles[texture]);
  vec2 corner = vec2(tile % u_atlasGrid.x, tile / u_atlasGrid.x) * float(u_atlasGrid.y) + 0.5 * float(u_atlasGrid.z);
  return (corner + uv * float(u_atlasGrid.z)) / u_atlasSize;
}
