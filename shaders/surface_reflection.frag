#version 450 core
// The reflection pass's march from water and glass, at the pass's resolution: drawn over the
// translucent quads nearest the camera (a depth-only draw of them went first, so each pixel marches
// once), it writes what the reflected ray sees, unweighted; the translucent pass looks it up
// (lib/reflection_upsample.glsl) and weighs it by Fresnel at its own pixels.

#include "lib/block_surface.glsl"
#include "lib/lighting.glsl"
#include "lib/sky.glsl"
#include "lib/ssr.glsl"
#ifdef WAVES
#include "lib/waves.glsl"
#endif

uniform float u_minSmoothness;

flat in float v_water;

layout(location = OUT_COLOR) out vec4 o_reflected;     // rgb: the reflected light; a: 1 hit, 0 sky
layout(location = OUT_REFLECTION_HIT) out vec4 o_hit;  // xy: hit screen uv; z: 1 hit, 0 none, -1 not marched; w: depth
layout(location = OUT_REFLECTION_SURFACE) out vec4 o_surface;  // xyz: the normal marched from; w: sky light

void main() {
  AtlasCoord at = atlasCoord();
  vec3 albedo = atlasTexel(u_atlasAlbedo, at).rgb * v_tint;
  Material m = labpbrMaterial(specularTexelAt(at), albedo);
  vec3 vertexNormal = vertexNormal();
#ifdef NO_NORMAL_MAPS
  vec3 normal = vertexNormal;
#else
  vec3 normal = mappedNormal(normalTexelAt(at));
#endif
#ifdef WAVES
  if (v_water > 0.5 && vertexNormal.y > 0.5) normal = waveNormal(v_position);
#endif
  // Seen from behind (under water the pass draws back faces): the face turns to the camera, and a
  // ray that hits nothing sees the water.
  bool behind = !gl_FrontFacing;
  if (behind) {
    normal = -normal;
    vertexNormal = -vertexNormal;
  }
  o_surface = vec4(normal, v_light.y);
  if (m.smoothness < u_minSmoothness) {
    o_reflected = vec4(0.0);
    o_hit = vec4(0.0, 0.0, -1.0, -1.0);
    return;
  }
  vec3 toViewer = -v_position / max(length(v_position), 1e-6);
  vec3 dir = reflect(-toViewer, normal);
  dir = normalize(dir - vertexNormal * min(dot(dir, vertexNormal) - 0.01, 0.0));
  vec2 hitUv;
  bool hit = march(v_position + vertexNormal * 0.02, dir, hitUv);
  vec3 missed = behind ? u_waterFog : reflectedSky(v_position, dir, v_light.y);
  o_reflected = vec4(reflectedLight(missed, hit, hitUv), hit ? 1.0 : 0.0);
  o_hit = vec4(hit ? hitUv : vec2(0.0), hit ? 1.0 : 0.0, 1.0 / gl_FragCoord.w);
}
