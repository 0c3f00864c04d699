#version 450 core
// Shadow pass: depth only; with CUTOUT, texels the G-buffer pass discards cast no shadow either.

layout(binding = UNIT_ATLAS_ALBEDO) uniform sampler2D u_atlasAlbedo;

in vec2 v_uv;

void main() {
#ifdef CUTOUT
  if (texture(u_atlasAlbedo, v_uv).a < 0.5) discard;
#endif
}
