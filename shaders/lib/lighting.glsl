// LabPBR lighting in linear light, shared by the deferred lighting pass and the translucent forward
// pass. Units: a white diffuse surface facing a light of colour c reflects c (no 1/pi), so the
// specular lobes below carry the matching factor of pi.

#include "lib/labpbr.glsl"

uniform vec3 u_toLight;     // unit, towards the shadow-casting light (sun or moon)
uniform vec3 u_lightColor;  // its radiance, already faded to 0 at the horizon
uniform vec3 u_ambientTint; // colour of sky light (the lightmap gives its brightness)
uniform bool u_materialAo;  // use the _n blue channel
// The lightmap's colours this frame (core/lightmap.h, LightmapColours).
uniform vec3 u_lightmapSky;
uniform vec3 u_lightmapBlock;
uniform float u_lightmapFloor;

// Radiance scales against the sun's ~3 at noon (day_cycle.h): full sky light as ambient, block light
// at level 15, emission at full strength, and the floor that keeps unlit caves from pure black.
const float kSkyAmbient = 1.5;
const float kBlockLight = 3.0;
const float kEmissiveStrength = 6.0;
const float kBaseLight = 0.05;
const float kPi = 3.14159265;

struct Surface {
  vec3 albedo;        // linear, vertex AO applied
  vec3 normal;        // mapped surface normal, unit
  vec3 vertexNormal;  // unit
  vec4 spec;          // raw LabPBR _s
  float blockLight, skyLight;  // 0..1
  float materialAo;   // 1 = none
};

// (1 - cos)^5 by multiplication: pow() is an exp2 and a log2, many times dearer on a CPU rasterizer.
float schlickWeight(float cosTheta) {
  float m = 1.0 - clamp(cosTheta, 0.0, 1.0);
  float m2 = m * m;
  return m2 * m2 * m;
}

vec3 fresnelSchlick(vec3 f0, float cosTheta) { return f0 + (1.0 - f0) * schlickWeight(cosTheta); }

// Lagarde's roughness-aware Fresnel for light from the whole hemisphere (no single half vector).
vec3 fresnelAmbient(vec3 f0, float cosTheta, float roughness) {
  return f0 + (max(vec3(1.0 - roughness), f0) - f0) * schlickWeight(cosTheta);
}

// Specular lobe times pi, without Fresnel; NdotL is applied by the caller.
float specularLobe(float NdotH, float NdotV, float NdotL, float roughness) {
  float a = max(roughness, 0.002);  // a perfect mirror would be an infinitely thin lobe
#ifdef SPECULAR_GGX
  float a2 = a * a;
  float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
  float D = a2 / (kPi * d * d);
  float vis = 0.5 / max(NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2) + NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2), 1e-5);
  return kPi * D * vis;
#else
  // Energy-conserving Blinn-Phong: the exponent matching GGX's alpha, normalised by (n + 8) / 8.
  float n = min(2.0 / (a * a) - 2.0, 8192.0);
  return (n + 8.0) / 8.0 * pow(NdotH, n);
#endif
}

// Vanilla's brightness curve f / (4 - 3f) of a level / 15 in [0, 1] (the divisor stays >= 1).
float levelBrightness(float f) {
  f = clamp(f, 0.0, 1.0);
  return f / (4.0 - 3.0 * f);
}

// The lightmap (core/lightmap.h) at the G-buffer's smooth levels, block and sky light / 15: its own sum
// evaluated here costs a software rasterizer far less than a filtered lookup in a 16x16 table.
vec3 lightmapAt(float block, float sky) {
  return clamp(u_lightmapFloor + u_lightmapSky * levelBrightness(sky) + u_lightmapBlock * levelBrightness(block), 0.0, 1.0);
}

// The direct light's shadow term (0 = in shadow, 1 = lit): the shadow map's lit fraction gated by sky
// light. The lighting pass keeps it in the HDR target's alpha, for the shadow-error report.
float shadowTerm(Surface s, float visibility) {
#ifdef SHADOWS
  return step(0.5 / 15.0, s.skyLight) * visibility;
#else
  return smoothstep(0.5, 1.0, s.skyLight) * visibility;
#endif
}

// Light leaving the surface towards `toViewer` (unit). `visibility`: the shadow map's lit fraction
// (1 without shadows); `transmittance`: the colour left after translucent casters (white without).
vec3 shade(Surface s, vec3 toViewer, float visibility, vec3 transmittance) {
  Material m = labpbrMaterial(s.spec, s.albedo);
  vec3 N = s.normal;
  float NdotV = max(dot(N, toViewer), 1e-4);
  vec3 kd = m.metal ? vec3(0.0) : vec3(1.0);

  // Direct light. Surfaces whose geometry faces away are simply unlit. No sky light means no sun,
  // whatever the shadow map says (a sealed cave); without a shadow map, sky light also stands in for
  // occlusion, fading the sun out where little of it reaches.
  float facing = smoothstep(0.0, 0.05, dot(s.vertexNormal, u_toLight));
  float NdotL = max(dot(N, u_toLight), 0.0) * facing * shadowTerm(s, visibility);
  vec3 color = vec3(0.0);
  if (NdotL > 0.0) {
    vec3 halfway = u_toLight + toViewer;
    float len = length(halfway);
    vec3 H = len > 1e-4 ? halfway / len : N;  // light straight behind the viewer's back: no half vector
    vec3 F = fresnelSchlick(m.f0, dot(H, toViewer));
    float lobe = specularLobe(max(dot(N, H), 0.0), NdotV, NdotL, m.roughness);
    color += u_lightColor * transmittance * NdotL * (kd * (1.0 - F) * s.albedo + F * lobe);
  }

  // Ambient: sky light from the lightmap, split into diffuse and a Fresnel reflection of the sky;
  // block light has no direction here (its sources' positions are unknown), so metals reflect it by F0.
  float ao = u_materialAo ? s.materialAo : 1.0;
  vec3 sky = lightmapAt(0.0, s.skyLight);
  vec3 block = max(lightmapAt(s.blockLight, s.skyLight) - sky, 0.0);
  vec3 Fa = fresnelAmbient(m.f0, NdotV, m.roughness);
  color += ao * (kSkyAmbient * sky * u_ambientTint * (kd * (1.0 - Fa) * s.albedo + Fa) +
                 kBlockLight * block * (kd * s.albedo + (1.0 - kd) * m.f0));
  color += ao * kBaseLight * s.albedo;
  color += s.albedo * m.emission * kEmissiveStrength;
  return color;
}
