#version 450 core
// G-buffer pass: opaque and (with CUTOUT) alpha-tested blocks. Layout: engine/render/gbuffer_layout.h.

#include "lib/block_surface.glsl"
#include "lib/gbuffer_albedo.glsl"

layout(location = GB_ALBEDO) out vec4 o_albedo;
layout(location = GB_NORMALS) out vec4 o_normals;
#ifndef NO_SPECULAR_MAPS
layout(location = GB_SPECULAR) out vec4 o_specular;
#endif
layout(location = GB_LIGHT) out vec4 o_light;

void main() {
  AtlasCoord at = atlasCoord();
  vec4 albedo = atlasTexel(u_atlasAlbedo, at);
#ifdef CUTOUT
  if (albedo.a < 0.5) discard;
#endif
  vec4 normalTexel = normalTexelAt(at);
  o_albedo = vec4(encodeAlbedo(albedo.rgb * v_tint * vertexAo()), normalTexel.b);
#ifdef NO_NORMAL_MAPS
  o_normals = vec4(octEncode(vertexNormal()), 0.0, 0.0);  // RG16F: the surface normal is the vertex normal
#else
  o_normals = vec4(octEncode(mappedNormal(normalTexel)), octEncode(vertexNormal()));
#endif
#ifndef NO_SPECULAR_MAPS
  o_specular = specularTexelAt(at);
#endif
  o_light = vec4(v_light, 1.0);
}
