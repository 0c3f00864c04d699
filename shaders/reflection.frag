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
#include "lib/ssr.glsl"

layout(binding = GB_ALBEDO) uniform sampler2D g_albedo;
layout(binding = GB_NORMALS) uniform sampler2D g_normals;
layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_LIGHT) uniform sampler2D g_light;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;

uniform float u_minSmoothness;
uniform ivec2 u_targetSize;  // this pass's

layout(location = OUT_COLOR) out vec4 o_reflection;  // rgb: added to the lit scene; a: 1 hit, 0 sky
layout(location = OUT_REFLECTION_HIT) out vec4 o_hit;  // xy: hit screen uv; z: 1 hit, 0 none; w: depth

void main() {
  ivec2 size = textureSize(g_depth, 0);
  ivec2 pixel = pixelUnder(size, u_targetSize);
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;  // the G-buffer pixel's own centre
  float depth = texelFetch(g_depth, pixel, 0).r;
  vec3 position = unproject(ndc, depth);
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

  vec2 hitUv;
  bool hit = march(position + vertexNormal * 0.02, dir, hitUv);
  vec3 reflected = reflectedLight(reflectedSky(position, dir, skyLight), hit, hitUv);

  // What the lighting pass reflected instead: sky light as a uniform environment.
  vec3 ambient = kSkyAmbient * lightmapAt(0.0, skyLight) * u_ambientTint;
  float ao = u_materialAo ? albedo.a : 1.0;
  float weight = smoothstep(u_minSmoothness, 1.0, m.smoothness);
  vec3 added = ao * weight * fresnelAmbient(m.f0, NdotV, m.roughness) * (reflected - ambient);
  o_reflection = vec4(foggedLight(added, position), hit ? 1.0 : 0.0);  // fogged as the scene was
  o_hit = vec4(hit ? hitUv : vec2(0.0), hit ? 1.0 : 0.0, viewDepth(depth));
}
