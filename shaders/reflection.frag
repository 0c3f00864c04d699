#version 450 core
// Screen-space reflections of smooth surfaces. The reflected view ray is marched against the depth
// buffer (steps growing with the distance, then a binary refinement); at a hit it takes the lit
// scene's colour there, else the sky in the reflected direction, gated by the surface's sky light so
// a cave never mirrors a bright sky. Out goes what to add to the lit scene: the reflection in place of
// the lighting pass's uniform sky term (lib/lighting.glsl), weighted by Fresnel and faded in with
// smoothness, so rough surfaces keep the ambient term with no hard cut.

#include "lib/gbuffer_albedo.glsl"
#include "lib/octahedral.glsl"
#include "lib/screen_position.glsl"
#include "lib/lighting.glsl"
#include "lib/sky.glsl"

layout(binding = GB_ALBEDO) uniform sampler2D g_albedo;
layout(binding = GB_NORMALS) uniform sampler2D g_normals;
layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_LIGHT) uniform sampler2D g_light;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;
layout(binding = UNIT_REFLECTION_SCENE) uniform sampler2D u_scene;

uniform mat4 u_viewProjection;  // camera-relative
uniform vec3 u_forward;         // unit view direction: depth along it decides in front or behind
uniform int u_maxSteps;
uniform float u_thickness;      // blocks a hit may lie behind the depth buffer's surface
uniform float u_maxDistance;    // blocks
uniform float u_minSmoothness;

layout(location = OUT_COLOR) out vec4 o_reflection;  // rgb: added to the lit scene; a: 1 hit, 0 sky
layout(location = OUT_REFLECTION_HIT) out vec4 o_hit;  // xy: hit screen uv; z: 1 hit, 0 none; w: distance

ivec2 g_size;

bool offScreen(vec2 uv) { return any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))); }

// Where `p` lands on screen; false behind the camera.
bool screenOf(vec3 p, out vec2 uv) {
  vec4 clip = u_viewProjection * vec4(p, 1.0);
  uv = clip.xy / max(clip.w, 1e-4) * 0.5 + 0.5;
  return clip.w > 1e-4;
}

// How far `p` lies behind the depth buffer's surface at its pixel (negative: in front). 0: off
// screen or behind the camera; 1: over sky (nothing to hit there); 2: measured.
int behindBy(vec3 p, out float behind, out vec2 uv) {
  behind = 0.0;
  if (!screenOf(p, uv) || offScreen(uv)) return 0;
  float depth = texelFetch(g_depth, ivec2(uv * vec2(g_size)), 0).r;
  if (depth >= 1.0) return 1;
  behind = dot(p - unproject(uv * 2.0 - 1.0, depth), u_forward);
  return 2;
}

bool march(vec3 origin, vec3 dir, out vec2 hitUv) {
  float near = 0.0;
  for (int i = 1; i <= u_maxSteps; ++i) {
    float f = float(i) / float(u_maxSteps);
    float t = u_maxDistance * f * f;  // fine steps near the surface, where most hits are
    float behind;
    vec2 uv;
    int seen = behindBy(origin + dir * t, behind, uv);
    if (seen == 0) return false;  // the ray left the screen: what it would hit is not in the image
    if (seen == 2 && behind > 0.0 && behind < u_thickness + t * 0.02) {
      float far = t;
      for (int k = 0; k < 6; ++k) {  // the crossing between the last point in front and this one
        float mid = 0.5 * (near + far);
        if (behindBy(origin + dir * mid, behind, uv) == 2 && behind > 0.0) far = mid; else near = mid;
      }
      return screenOf(origin + dir * far, hitUv) && !offScreen(hitUv);
    }
    if (seen == 1 || behind <= 0.0) near = t;
  }
  return false;
}

// Screen edges hold no more of the reflected world: hits near them fade to the sky fallback.
float edgeFade(vec2 uv) {
  vec2 d = min(uv, 1.0 - uv);
  return smoothstep(0.0, 0.05, min(d.x, d.y));
}

void main() {
  g_size = textureSize(g_depth, 0);
  vec2 uv = v_ndc * 0.5 + 0.5;
  ivec2 pixel = clamp(ivec2(uv * vec2(g_size)), ivec2(0), g_size - 1);
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(g_size) * 2.0 - 1.0;  // the G-buffer pixel's own centre
  vec3 position = unproject(ndc, texelFetch(g_depth, pixel, 0).r);
  vec4 albedo = texelFetch(g_albedo, pixel, 0);
  vec4 normals = texelFetch(g_normals, pixel, 0);
#ifdef NO_NORMAL_MAPS
  vec3 normal = octDecode(normals.xy), vertexNormal = normal;
#else
  vec3 normal = octDecode(normals.xy), vertexNormal = octDecode(normals.zw);
#endif
  float skyLight = texelFetch(g_light, pixel, 0).y;
  Material m = labpbrMaterial(texelFetch(g_specular, pixel, 0), decodeAlbedo(albedo.rgb));

  vec3 toViewer = -position / max(length(position), 1e-6);
  float NdotV = max(dot(normal, toViewer), 1e-4);
  vec3 dir = reflect(-toViewer, normal);
  // A mapped normal can send the ray into the block itself: keep it above the geometric surface.
  dir = normalize(dir - vertexNormal * min(dot(dir, vertexNormal) - 0.01, 0.0));

  vec3 reflected = skyColor(dir) * levelBrightness(skyLight);
  vec2 hitUv;
  bool hit = march(position + vertexNormal * 0.02, dir, hitUv);
  if (hit) reflected = mix(reflected, texture(u_scene, hitUv).rgb, edgeFade(hitUv));

  // What the lighting pass reflected instead: sky light as a uniform environment.
  vec3 ambient = kSkyAmbient * lightmapAt(0.0, skyLight) * u_ambientTint;
  float ao = u_materialAo ? albedo.a : 1.0;
  float weight = smoothstep(u_minSmoothness, 1.0, m.smoothness);
  vec3 added = ao * weight * fresnelAmbient(m.f0, NdotV, m.roughness) * (reflected - ambient);
  o_reflection = vec4(fogged(added, position, vec3(0.0)), hit ? 1.0 : 0.0);  // fogged as the scene was
  o_hit = vec4(hit ? hitUv : vec2(0.0), hit ? 1.0 : 0.0, length(position));
}
