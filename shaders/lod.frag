#version 450 core
// Far terrain into the G-buffer (layout: engine/render/gbuffer_layout.h): the cells' average colours,
// the surface's normal, full sky light; water as smooth as LabPBR's water, so reflections see the far sea.

#include "lib/color.glsl"
#include "lib/gbuffer_albedo.glsl"
#include "lib/octahedral.glsl"

layout(location = GB_ALBEDO) out vec4 o_albedo;
layout(location = GB_NORMALS) out vec4 o_normals;
#ifndef NO_SPECULAR_MAPS
layout(location = GB_SPECULAR) out vec4 o_specular;
#endif
layout(location = GB_LIGHT) out vec4 o_light;

in vec3 v_colour;
in vec3 v_normal;
in float v_water;

void main() {
  o_albedo = vec4(encodeAlbedo(srgbToLinear(v_colour)), 1.0);
#ifdef NO_NORMAL_MAPS
  o_normals = vec4(octEncode(normalize(v_normal)), 0.0, 0.0);
#else
  o_normals = vec4(octEncode(normalize(v_normal)), octEncode(normalize(v_normal)));
#endif
#ifndef NO_SPECULAR_MAPS
  // Water: smoothness 0.95, F0 0.02 (LabPBR's G in 1/255), no emission (alpha 1).
  o_specular = v_water > 0.5 ? vec4(0.95, 5.0 / 255.0, 0.0, 1.0) : vec4(0.0);
#endif
  o_light = vec4(0.0, 1.0, 1.0, 1.0);
}
