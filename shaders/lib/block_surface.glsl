// What the G-buffer and translucent passes share: a block fragment's albedo, normals and material.

#include "lib/atlas_sample.glsl"
#include "lib/octahedral.glsl"
#include "lib/labpbr.glsl"

layout(binding = UNIT_ATLAS_ALBEDO) uniform sampler2D u_atlasAlbedo;    // sRGB: reads linear
layout(binding = UNIT_ATLAS_NORMAL) uniform sampler2D u_atlasNormal;    // LabPBR _n
layout(binding = UNIT_ATLAS_SPECULAR) uniform sampler2D u_atlasSpecular;  // LabPBR _s, nearest

// With NO_NORMAL_MAPS / NO_SPECULAR_MAPS (no loaded pack has any _n / _s) the atlases hold only
// LabPBR's defaults, so those constants stand in and nothing is sampled: the same values, no fetch.
vec4 normalTexelAt(AtlasCoord at) {
#ifdef NO_NORMAL_MAPS
  return vec4(127.0 / 255.0, 127.0 / 255.0, 1.0, 1.0);  // labpbr::kDefaultNormal
#else
  return atlasTexel(u_atlasNormal, at);
#endif
}

vec4 specularTexelAt(AtlasCoord at) {
#ifdef NO_SPECULAR_MAPS
  return vec4(0.0);  // labpbr::kDefaultSpecular
#else
  return atlasTexel(u_atlasSpecular, at);
#endif
}

in vec3 v_position;
in vec3 v_tint;  // linear
in vec3 v_light;
// The face's frame, looked up per vertex: indexing the tables here would gather per pixel.
flat in vec3 v_normal;
flat in vec3 v_tangent;
flat in vec3 v_up;

// Vanilla-like corner darkening: AO level 0..3 -> 0.4 .. 1.
float vertexAo() { return mix(0.4, 1.0, v_light.z); }

vec3 vertexNormal() { return v_normal; }

// The normal map in world space, faded back to the vertex normal where it would face away from the
// viewer (the seeds' smoothstep), so no pixel is lit from behind.
vec3 mappedNormal(vec4 normalTexel) {
  vec3 N = v_normal;
  mat3 tbn = mat3(v_tangent, v_up, N);
  vec3 n = tbn * labpbrNormal(normalTexel);
  vec3 viewDir = v_position / max(length(v_position), 1e-6);
  float fade = smoothstep(-0.5, 0.5, dot(viewDir, n));
  n = mix(n, N, fade);
  float len = length(n);
  return len > 1e-4 ? n / len : N;  // n and N are never opposite (z >= 0), but stay safe
}
