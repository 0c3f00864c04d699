// A prop fragment's glTF metallic-roughness material turned into what blocks carry: linear albedo,
// mapped and vertex normals, and a LabPBR _s texel, so lighting, shadows and debug views treat props
// like blocks. Mapping: smoothness = 1 - sqrt(roughness) (LabPBR's roughness is (1 - smoothness)^2);
// metallic >= 0.5 is a metal with the albedo as F0 (G = 255), below it glTF's dielectric F0 0.04
// (G = 10); emission scales the albedo in LabPBR, so glTF's emissive colour becomes the strength that
// matches its luminance (its hue follows the albedo); occlusion is the material AO.

#include "lib/octahedral.glsl"

layout(binding = UNIT_PROP_BASE_COLOR) uniform sampler2D u_baseColorMap;  // sRGB: reads linear
layout(binding = UNIT_PROP_METALLIC_ROUGHNESS) uniform sampler2D u_metallicRoughnessMap;  // G roughness, B metallic
layout(binding = UNIT_PROP_NORMAL) uniform sampler2D u_normalMap;  // OpenGL convention, tangent space
layout(binding = UNIT_PROP_EMISSIVE) uniform sampler2D u_emissiveMap;  // sRGB
layout(binding = UNIT_PROP_OCCLUSION) uniform sampler2D u_occlusionMap;  // R

uniform vec4 u_baseColorFactor;
uniform float u_metallic, u_roughness;
uniform vec3 u_emissiveFactor;
uniform float u_normalScale, u_occlusionStrength;
uniform float u_alphaCutoff;
uniform bool u_hasNormalMap;

in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv;
in vec2 v_light;

struct PropSurface {
  vec4 baseColor;     // linear rgb, alpha
  vec3 normal;        // mapped, unit
  vec3 vertexNormal;  // unit, towards the side being drawn
  vec4 spec;          // LabPBR _s
  float occlusion;    // material AO, 1 = none
};

vec3 safeNormalize(vec3 v, vec3 fallback) {
  float len = length(v);
  return len > 1e-6 ? v / len : fallback;
}

PropSurface propSurface() {
  PropSurface s;
  s.baseColor = texture(u_baseColorMap, v_uv) * u_baseColorFactor;
  // A double-sided material's back faces are lit as their own side.
  vec3 N = safeNormalize(v_normal, vec3(0.0, 1.0, 0.0));
  if (!gl_FrontFacing) N = -N;
  s.vertexNormal = N;
  s.normal = N;
#ifndef NO_NORMAL_MAPS
  if (u_hasNormalMap) {
    vec3 t = v_tangent.xyz - N * dot(N, v_tangent.xyz);  // Gram-Schmidt: interpolation bends it
    float tl = length(t);
    if (tl > 1e-5) {
      t /= tl;
      vec3 b = cross(N, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
      vec3 tn = texture(u_normalMap, v_uv).xyz * 2.0 - 1.0;
      tn.xy *= u_normalScale;
      vec3 n = safeNormalize(t * tn.x + b * tn.y + N * max(tn.z, 0.0), N);
      // As for blocks: fade back to the vertex normal where the mapped one would face away.
      vec3 viewDir = v_position / max(length(v_position), 1e-6);
      s.normal = safeNormalize(mix(n, N, smoothstep(-0.5, 0.5, dot(viewDir, n))), N);
    }
  }
#endif
  vec2 mr = clamp(texture(u_metallicRoughnessMap, v_uv).bg * vec2(u_metallic, u_roughness), 0.0, 1.0);
  vec3 emissive = texture(u_emissiveMap, v_uv).rgb * u_emissiveFactor;
  float strength = dot(emissive, LUMA_WEIGHTS) / max(dot(s.baseColor.rgb, LUMA_WEIGHTS), 1e-3);
  float emission = strength > 0.0 ? min(strength, 254.0 / 255.0) : 1.0;  // 255: none
  s.spec = vec4(1.0 - sqrt(mr.y), mr.x >= 0.5 ? 1.0 : 10.0 / 255.0, 0.0, emission);
  s.occlusion = 1.0 + u_occlusionStrength * (texture(u_occlusionMap, v_uv).r - 1.0);
  return s;
}
