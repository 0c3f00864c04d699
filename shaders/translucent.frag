#version 450 core
// Translucent pass: water and glass, lit forward with the deferred pass's lighting and blended over
// the lit scene (premultiplied alpha: blend ONE, ONE_MINUS_SRC_ALPHA).

#include "lib/block_surface.glsl"
#include "lib/lighting.glsl"
#include "lib/sky.glsl"
#ifdef SHADOWS
#include "lib/shadow.glsl"
#endif
#ifdef REFLECTIONS
#include "lib/ssr.glsl"

uniform float u_minSmoothness;

// What the surface reflects beyond what `shade` gave it (its sky ambient, weighed by the coverage
// `alpha` it is blended with): the reflected scene or sky, by Fresnel, faded in with smoothness.
// Added unweighted by alpha, as a reflection lies on top of what the surface lets through.
vec3 reflection(Surface s, vec3 toViewer, float alpha) {
  Material m = labpbrMaterial(s.spec, s.albedo);
  float weight = smoothstep(u_minSmoothness, 1.0, m.smoothness);
  vec3 dir = reflect(-toViewer, s.normal);
  dir = normalize(dir - s.vertexNormal * min(dot(dir, s.vertexNormal) - 0.01, 0.0));
  vec2 hitUv;
  bool hit = weight > 0.0 && march(v_position + s.vertexNormal * 0.02, dir, hitUv);
  vec3 reflected = reflectedLight(dir, s.skyLight, hit, hitUv);
  vec3 ambient = kSkyAmbient * lightmapAt(0.0, s.skyLight) * u_ambientTint;
  float NdotV = max(dot(s.normal, toViewer), 1e-4);
  return weight * fresnelAmbient(m.f0, NdotV, m.roughness) * (reflected - alpha * ambient);
}
#endif

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  AtlasCoord at = atlasCoord();
  vec4 albedo = atlasTexel(u_atlasAlbedo, at);
  vec4 normalTexel = normalTexelAt(at);
  Surface s;
  s.albedo = albedo.rgb * v_tint * vertexAo();
#ifdef NO_NORMAL_MAPS
  s.normal = vertexNormal();
#else
  s.normal = mappedNormal(normalTexel);
#endif
  s.vertexNormal = vertexNormal();
  s.spec = specularTexelAt(at);
  s.blockLight = v_light.x;
  s.skyLight = v_light.y;
  s.materialAo = normalTexel.b;
  vec3 toViewer = -v_position / max(length(v_position), 1e-6);
  float visibility = 1.0;
  vec3 transmittance = vec3(1.0);
#ifdef SHADOWS
  float cosTheta = dot(s.vertexNormal, u_toLight);
  if (u_shadowLive && cosTheta > 0.0) {
    ShadowLookup lookup = shadowLookup(v_position, s.vertexNormal, cosTheta);
    visibility = shadowVisibility(lookup, gl_FragCoord.xy);
    transmittance = shadowTransmittance(lookup);
  }
#endif
  vec3 lit = fogged(shade(s, toViewer, visibility, transmittance), v_position, skyColor(-toViewer));
  o_color = vec4(lit * albedo.a, albedo.a);
#ifdef REFLECTIONS
  o_color.rgb += fogged(reflection(s, toViewer, albedo.a), v_position, vec3(0.0));
#endif
}
