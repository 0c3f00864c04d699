#version 450 core
// Deferred lighting: reads the G-buffer, writes linear HDR radiance; distant geometry fades into the
// sky colour (fog). Runs only where something was drawn: the depth test leaves sky pixels (depth 1)
// to sky.frag.

#include "lib/gbuffer_albedo.glsl"
#include "lib/octahedral.glsl"
#include "lib/screen_position.glsl"
#include "lib/lighting.glsl"
#include "lib/sky.glsl"
#ifdef SHADOWS
#include "lib/shadow.glsl"
#endif

layout(binding = GB_ALBEDO) uniform sampler2D g_albedo;
layout(binding = GB_NORMALS) uniform sampler2D g_normals;
layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_LIGHT) uniform sampler2D g_light;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(g_depth, pixel, 0).r;
  vec3 viewDir = viewDirection();
  vec3 sky = skyColor(viewDir);
  vec3 position = unproject(v_ndc, depth);
  vec4 albedo = texelFetch(g_albedo, pixel, 0);
  vec4 normals = texelFetch(g_normals, pixel, 0);
  vec4 light = texelFetch(g_light, pixel, 0);
  Surface s;
  s.albedo = decodeAlbedo(albedo.rgb);
  s.materialAo = albedo.a;
#ifdef NO_NORMAL_MAPS
  s.normal = s.vertexNormal = octDecode(normals.xy);  // the only normal kept (gbuffer_layout.h)
#else
  s.normal = octDecode(normals.xy);
  s.vertexNormal = octDecode(normals.zw);
#endif
#ifdef NO_SPECULAR_MAPS
  s.spec = vec4(0.0);  // every texel holds LabPBR's default _s: nothing to read
#else
  s.spec = texelFetch(g_specular, pixel, 0);
#endif
  s.blockLight = light.x;
  s.skyLight = light.y;
  float visibility = 1.0;
  vec3 transmittance = vec3(1.0);
#ifdef SHADOWS
  float cosTheta = dot(s.vertexNormal, u_toLight);
  if (u_shadowLive && cosTheta > 0.0 && s.skyLight > 0.0) {
    ShadowLookup lookup = shadowLookup(position, s.vertexNormal, cosTheta);
    visibility = shadowVisibility(lookup, gl_FragCoord.xy);
    transmittance = shadowTransmittance(lookup);
  }
#endif
  visibility *= cloudShadow(position);
  vec3 color = fogged(shade(s, -viewDir, visibility, transmittance), position, sky);
  // Clouds between the camera and the surface: seen from above them, or on a peak beyond them.
  o_color = vec4(behindClouds(color, vec3(0.0), viewDir, length(position)), shadowTerm(s, visibility));
}
