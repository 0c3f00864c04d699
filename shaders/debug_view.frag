#version 450 core
// Debug views: one G-buffer channel on screen, sRGB-encoded where it holds colour.

#include "lib/color.glsl"
#include "lib/gbuffer_albedo.glsl"
#include "lib/octahedral.glsl"
#include "lib/labpbr.glsl"
#include "lib/view_depth.glsl"

layout(binding = GB_ALBEDO) uniform sampler2D g_albedo;
layout(binding = GB_NORMALS) uniform sampler2D g_normals;
layout(binding = GB_SPECULAR) uniform sampler2D g_specular;
layout(binding = GB_LIGHT) uniform sampler2D g_light;
layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;
layout(binding = UNIT_REFLECTION) uniform sampler2D u_reflection;
layout(binding = UNIT_REFLECTION_HITS) uniform sampler2D u_hits;
layout(binding = UNIT_SURFACE_REFLECTION) uniform sampler2D u_surfaceReflection;
layout(binding = UNIT_SURFACE_REFLECTION_HITS) uniform sampler2D u_surfaceHits;
uniform bool u_reflected;       // the reflection pass marched from opaque surfaces this frame
uniform bool u_surfaceMarched;  // ... and from water and glass (else those views are black)

uniform int u_view;         // DebugView (core/render_settings.h): DEBUG_VIEW_ALBEDO, ...

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
  if (u_view == DEBUG_VIEW_ALBEDO) c = linearToSrgb(albedo.rgb);
  else if (u_view == DEBUG_VIEW_NORMAL) c = octDecode(normals.xy) * 0.5 + 0.5;
#ifdef NO_NORMAL_MAPS
  else if (u_view == DEBUG_VIEW_VERTEX_NORMAL) c = octDecode(normals.xy) * 0.5 + 0.5;  // RG16F: vertex's only
#else
  else if (u_view == DEBUG_VIEW_VERTEX_NORMAL) c = octDecode(normals.zw) * 0.5 + 0.5;
#endif
  else if (u_view == DEBUG_VIEW_SPECULAR) c = spec.rgb;
  else if (u_view == DEBUG_VIEW_LIGHTMAP) c = vec3(light.x, light.y, 0.0);
  else if (u_view == DEBUG_VIEW_DEPTH) {
    // Linear depth, log-scaled so near and far both show.
    float linear = viewDepth(depth);
    c = vec3(log2(max(linear, u_nearFar.x) / u_nearFar.x) / log2(u_nearFar.y / u_nearFar.x));
  } else if (u_view == DEBUG_VIEW_AO) c = vec3(light.z, albedo.a, 0.0);
  else if (u_view == DEBUG_VIEW_EMISSION) c = vec3(labpbrMaterial(spec, albedo.rgb).emission);
  else if (u_view >= DEBUG_VIEW_REFLECTION_HITS) {
    // Hits white, rays that found nothing blue, pixels not marched black; or what the pass added to
    // opaque surfaces and, over them, the light water and glass reflect (before Fresnel).
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(g_depth, 0));
    vec4 hit = u_reflected ? texture(u_hits, uv) : vec4(0.0, 0.0, -1.0, -1.0);
    vec3 reflected = u_reflected ? abs(texture(u_reflection, uv).rgb) : vec3(0.0);
    vec4 surfaceHit = u_surfaceMarched ? texture(u_surfaceHits, uv) : vec4(0.0, 0.0, -1.0, -1.0);
    if (surfaceHit.z > -0.5) {
      hit = surfaceHit;
      reflected = texture(u_surfaceReflection, uv).rgb;
      depth = 0.0;  // shown over the sky too
    }
    if (u_view == DEBUG_VIEW_REFLECTION_HITS) {
      c = hit.z > 0.5 ? vec3(1.0) : hit.z > -0.5 ? vec3(0.1, 0.2, 0.8) : vec3(0.0);
    } else {
      c = linearToSrgb(clamp(reflected * 0.5, 0.0, 1.0));
    }
  }
  if (depth >= 1.0 && u_view != DEBUG_VIEW_DEPTH) c = vec3(0.0);
  o_color = vec4(c, 1.0);
}
