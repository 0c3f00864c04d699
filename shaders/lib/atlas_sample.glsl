// Block texels from the atlas. `v_uv` counts textures across the face, beyond 1 on a merged quad
// (mesh/face_merge.h): it repeats inside the tile (the band around each tile holds its wrapped edges,
// so filtering at a seam reads the right texels), and the mip level comes from the unrepeated UV's
// derivatives, so every pixel reads what it would on the faces the quad replaced.

uniform ivec3 u_atlasGrid;  // columns, slot size, tile size (texels)
uniform vec2 u_atlasSize;   // texels
// Below 1, finer mip levels than the pixel's footprint: TAA at a render scale reconstructs the target's
// detail from several frames, so textures are read for the target's pixels, not the scene's.
uniform float u_textureDetail = 1.0;

in vec2 v_uv;         // textures across, v = 0 at the top row
flat in vec2 v_tile;  // the tile's top left corner in atlas UV (lib/atlas_uv.glsl)

struct AtlasCoord {
  vec2 uv, dx, dy;
};

AtlasCoord atlasCoord() {
  vec2 scale = float(u_atlasGrid.z) / u_atlasSize;
  vec2 footprint = scale * u_textureDetail;
  return AtlasCoord(v_tile + fract(v_uv) * scale, dFdx(v_uv) * footprint, dFdy(v_uv) * footprint);
}

vec4 atlasTexel(sampler2D atlas, AtlasCoord at) { return textureGrad(atlas, at.uv, at.dx, at.dy); }
