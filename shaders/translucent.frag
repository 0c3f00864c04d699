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
#include "lib/view_depth.glsl"
#include "lib/reflection_upsample.glsl"

layout(binding = UNIT_SSR_DEPTH) uniform sampler2D u_sceneDepth;        // the opaque scene's depth
layout(binding = UNIT_REFLECTION_SCENE) uniform sampler2D u_scene;     // the lit opaque scene
layout(binding = UNIT_REFLECTION) uniform sampler2D u_reflected;       // the reflection pass's march
layout(binding = UNIT_REFLECTION_HITS) uniform sampler2D u_reflectedHits;  // from these surfaces
uniform bool u_marched;  // the reflection pass marched from translucent surfaces this frame
uniform float u_minSmoothness;

// What the reflection pass's ray saw from here, else (another surface lies nearer, or none was
// marched) `fallback`.
vec3 marchedOr(vec3 fallback) {
  if (!u_marched) return fallback;
  vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_scene, 0));
  vec4 marched = upsampledReflection(u_reflected, u_reflectedHits, uv, 1.0 / gl_FragCoord.w);
  return mix(fallback, marched.rgb, smoothstep(0.2, 0.5, marched.w));
}

// What the surface reflects beyond what `shade` gave it (its sky ambient, weighed by the coverage
// `alpha` it is blended with): what the reflection pass's ray saw, else the sky in the reflected
// direction dimmed by the sky light; by Fresnel, faded in with smoothness. Added unweighted by alpha,
// as a reflection lies on top of what the surface lets through.
vec3 reflection(Surface s, vec3 toViewer, float alpha) {
  Material m = labpbrMaterial(s.spec, s.albedo);
  float weight = smoothstep(u_minSmoothness, 1.0, m.smoothness);
  vec3 dir = reflect(-toViewer, s.normal);
  dir = normalize(dir - s.vertexNormal * min(dot(dir, s.vertexNormal) - 0.01, 0.0));
  vec3 reflected = marchedOr(skyAlong(v_position, dir) * levelBrightness(s.skyLight));
  vec3 ambient = kSkyAmbient * lightmapAt(0.0, s.skyLight) * u_ambientTint;
  float NdotV = max(dot(s.normal, toViewer), 1e-4);
  return weight * fresnelAmbient(m.f0, NdotV, m.roughness) * (reflected - alpha * ambient);
}

// What water lets through, bent: the opaque scene behind it, looked up a little off along the surface
// normal (less with distance), unless what lies there is in front of the water (nothing in front is
// smeared in).
vec3 refracted(vec3 normal) {
  vec2 size = vec2(textureSize(u_scene, 0));
  vec2 straight = gl_FragCoord.xy / size;
  vec2 uv = clamp(straight + normal.xz * (0.6 / max(length(v_position), 1.0)), vec2(0.0), vec2(1.0));
  float depth = texelFetch(u_sceneDepth, ivec2(uv * size), 0).r;
  if (viewDepth(depth) < 1.0 / gl_FragCoord.w) uv = straight;  // what lies there is in front
  return texelFetch(u_scene, ivec2(uv * size), 0).rgb;  // the texel the depth check read
}

// Water's surface from below: what lies above, bent, inside Snell's window, and the water below
// reflected at its edge and beyond (total internal reflection), by Fresnel on the air side's angle.
// What it lets through was faded by the water on its way here (lib/sky.glsl), and is not again.
vec3 fromBelow(Surface s, vec3 toViewer) {
  float cosI = clamp(dot(s.normal, toViewer), 0.0, 1.0);
  float sinT2 = 1.33 * 1.33 * (1.0 - cosI * cosI);
  float F = sinT2 >= 1.0 ? 1.0 : fresnelSchlick(vec3(0.02), sqrt(1.0 - sinT2)).x;
  return mix(refracted(s.normal), marchedOr(u_waterFog), F);
}
#endif

flat in float v_water;  // 1 on water's quads
#ifdef WAVES
#include "lib/waves.glsl"
#endif

layout(location = OUT_COLOR) out vec4 o_color;
layout(location = OUT_REACTIVE) out float o_reactive;  // water changes by itself (TAA's reactive mask)

void main() {
  o_reactive = v_water;
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
  // Seen from behind (under water the pass draws back faces): the face turns to the camera.
  bool behind = !gl_FrontFacing;
  if (behind) {
    s.normal = -s.normal;
    s.vertexNormal = -s.vertexNormal;
  }
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
  visibility *= cloudShadow(v_position);
  vec3 lit = fogged(shade(s, toViewer, visibility, transmittance), v_position, skyColor(-toViewer));
  // Clouds between the camera and the surface (seen from above them) cover it and what it lets through.
  vec4 clouds = cloudsAlong(vec3(0.0), -toViewer, length(v_position));
  lit = lit * (1.0 - clouds.a) + clouds.rgb;
  o_color = vec4(lit * albedo.a, albedo.a);
#ifdef REFLECTIONS
  if (v_water > 0.5 && behind) {
    o_color = vec4(fromBelow(s, toViewer), 1.0);
    return;
  }
  // Water draws what it lets through itself, refracted, and so covers what lay behind it whole.
  if (v_water > 0.5) o_color = vec4(o_color.rgb + refracted(s.normal) * (1.0 - albedo.a), 1.0);
  o_color.rgb += foggedLight(reflection(s, toViewer, albedo.a), v_position) * (1.0 - clouds.a);
#endif
}
