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

// What water lets through, bent: the opaque scene behind it, looked up a little off along the surface
// normal (less with distance), unless what lies there is in front of the water (nothing in front is
// smeared in).
vec3 refracted(vec3 normal) {
  vec2 size = vec2(textureSize(u_ssrScene, 0));
  vec2 straight = gl_FragCoord.xy / size;
  vec2 uv = clamp(straight + normal.xz * (0.6 / max(length(v_position), 1.0)), vec2(0.0), vec2(1.0));
  float depth = texelFetch(u_ssrDepth, ivec2(uv * size), 0).r;
  if (viewDepth(depth) < 1.0 / gl_FragCoord.w) uv = straight;  // what lies there is in front
  return texture(u_ssrScene, uv).rgb;
}
#endif

#if defined(WAVES) || defined(REFLECTIONS)
flat in float v_water;
#endif
#ifdef WAVES
uniform float u_waveTime;    // seconds of world time (wrapped at an hour)
uniform vec3 u_waveOrigin;   // the camera's world position wrapped at 256 blocks

// The normal of water's moving surface: four summed waves (direction, wavelength, height, speed),
// their slopes only (the geometry stays flat), so the surface ripples in light and reflections.
vec3 waveNormal(vec3 position) {
  vec2 p = position.xz + u_waveOrigin.xz;
  const vec4 waves[4] = vec4[4](vec4(0.96, 0.28, 6.0, 0.020), vec4(-0.55, 0.84, 3.7, 0.014),
                                vec4(0.31, -0.95, 2.3, 0.009), vec4(-0.88, -0.47, 1.3, 0.005));
  vec2 slope = vec2(0.0);
  for (int i = 0; i < 4; ++i) {
    float k = 6.2831853 / waves[i].z;
    float phase = k * dot(waves[i].xy, p) - sqrt(9.81 * k) * u_waveTime;
    slope += waves[i].xy * (waves[i].w * k * cos(phase));
  }
  return normalize(vec3(-slope.x, 1.0, -slope.y));
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
#ifdef WAVES
  if (v_water > 0.5 && s.vertexNormal.y > 0.5) s.normal = waveNormal(v_position);  // the top surface
#endif
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
  // Water draws what it lets through itself, refracted, and so covers what lay behind it whole.
  if (v_water > 0.5) o_color = vec4(o_color.rgb + refracted(s.normal) * (1.0 - albedo.a), 1.0);
  o_color.rgb += fogged(reflection(s, toViewer, albedo.a), v_position, vec3(0.0));
#endif
}
