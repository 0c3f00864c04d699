#version 450 core
// Debug views: one G-buffer channel on screen, sRGB-encoded where it holds colour.

#include "lib/color.glsl"
#include "lib/gbuffer_albedo.glsl"
#include "lib/octahedral.glsl"
#include "lib/labpbr.glsl"

layout(binding = GB_ALBEDO) uniform sampler2D g_albedo;
layout(binding = GB_NORMALS) uniform sampler2D g_normals;
layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_LIGHT) uniform sampler2D g_light;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;

uniform int u_view;         // index in kDebugViews (scene_file.h), 1..
uniform vec2 u_nearFar;

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(g_depth, p, 0).r;
  vec4 albedo = texelFetch(g_albedo, p, 0);
  albedo.rgb = decodeAlbedo(albedo.rgb);
  vec4 normals = texelFetch(g_normals, p, 0);
#ifdef NO_SPECULAR_MAPS
  vec4 spec = vec4(0.0);  // no _s target: every texel is LabPBR's default
#else
  vec4 spec = texelFetch(g_specular, p, 0);
#endif
  vec4 light = texelFetch(g_light, p, 0);
  vec3 c = vec3(0.0);
  if (u_view == 1) c = linearToSrgb(albedo.rgb);
  else if (u_view == 2) c = octDecode(normals.xy) * 0.5 + 0.5;
#ifdef NO_NORMAL_MAPS
  else if (u_view == 3) c = octDecode(normals.xy) * 0.5 + 0.5;  // RG16F: the vertex normal only
#else
  else if (u_view == 3) c = octDecode(normals.zw) * 0.5 + 0.5;
#endif
  else if (u_view == 4) c = spec.rgb;
  else if (u_view == 5) c = vec3(light.x, light.y, 0.0);
  else if (u_view == 6) {
    // Linear depth, log-scaled so near and far both show.
    float z = depth * 2.0 - 1.0;
    float linear = 2.0 * u_nearFar.x * u_nearFar.y / max(u_nearFar.y + u_nearFar.x - z * (u_nearFar.y - u_nearFar.x), 1e-6);
    c = vec3(log2(max(linear, u_nearFar.x) / u_nearFar.x) / log2(u_nearFar.y / u_nearFar.x));
  } else if (u_view == 7) c = vec3(light.z, albedo.a, 0.0);
  else if (u_view == 8) c = vec3(labpbrMaterial(spec, albedo.rgb).emission);
  if (depth >= 1.0 && u_view != 6) c = vec3(0.0);
  o_color = vec4(c, 1.0);
}
