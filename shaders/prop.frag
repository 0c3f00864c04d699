#version 450 core
// G-buffer pass for props: opaque and (with CUTOUT) alpha-masked glTF materials, encoded as blocks
// are (engine/render/gbuffer_layout.h): vertex AO 1, the voxel light at the vertices.

#include "lib/prop_surface.glsl"
#include "lib/gbuffer_albedo.glsl"

layout(location = GB_ALBEDO) out vec4 o_albedo;
layout(location = GB_NORMALS) out vec4 o_normals;
#ifndef NO_SPECULAR_MAPS
layout(location = GB_SPECULAR) out vec4 o_specular;
#endif
layout(location = GB_LIGHT) out vec4 o_light;

void main() {
  PropSurface s = propSurface();
#ifdef CUTOUT
  if (s.baseColor.a < u_alphaCutoff) discard;
#endif
  o_albedo = vec4(encodeAlbedo(s.baseColor.rgb), s.occlusion);
#ifdef NO_NORMAL_MAPS
  o_normals = vec4(octEncode(s.vertexNormal), 0.0, 0.0);
#else
  o_normals = vec4(octEncode(s.normal), octEncode(s.vertexNormal));
#endif
#ifndef NO_SPECULAR_MAPS
  o_specular = s.spec;
#endif
  o_light = vec4(v_light, 1.0, 1.0);
}
