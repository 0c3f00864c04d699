#version 450 core
// Translucent pass: water and glass, lit forward with the deferred pass's lighting and blended over
// the lit scene (premultiplied alpha: blend ONE, ONE_MINUS_SRC_ALPHA).

#include "lib/block_surface.glsl"
#include "lib/lighting.glsl"
#include "lib/sky.glsl"
#ifdef SHADOWS
#include "lib/shadow.glsl"
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
}
