// Block texels from the atlas. `v_uv` counts textures across the face, beyond 1 on a merged quad
// (mesh/face_merge.h): it repeats inside the tile (the band around each tile holds its wrapped edges,
// so filtering at a seam reads the right texels), and the mip level comes from the unrepeated UV's
// derivatives, so every pixel reads what it would on the faces the quad replaced.

uniform ivec3 u_atlasGrid;  // columns, slot size, tile size (texels)
uniform vec2 u_atlasSize;   // texels

in vec2 v_uv;         // textures across, v = 0 at the top row
flat in vec2 v_tile;  // the tile's top left corner in atlas UV (lib/atlas_uv.glsl)

struct AtlasCoord {
  vec2 uv, dx, dy;
};

AtlasCoord atlasCoord() {
  vec2 scale = float(u_atlasGrid.z) / u_atlasSize;
  return AtlasCoord(v_tile + fract(v_uv) * scale, dFdx(v_uv) * scale, dFdy(v_uv) * scale);
}

vec4 atlasTexel(sampler2D atlas, AtlasCoord at) { return textureGrad(atlas, at.uv, at.dx, at.dy); }
