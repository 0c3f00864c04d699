#version 450 core
// Translucent pass for props with alpha mode BLEND: lit forward like water and glass, blended over the
// lit scene with premultiplied alpha.

#include "lib/prop_surface.glsl"
#include "lib/lighting.glsl"
#include "lib/sky.glsl"
#ifdef SHADOWS
#include "lib/shadow.glsl"
#endif

layout(location = OUT_COLOR) out vec4 o_color;
layout(location = OUT_REACTIVE) out float o_reactive;  // a prop keeps still (TAA's reactive mask)

void main() {
  PropSurface p = propSurface();
  Surface s;
  s.albedo = p.baseColor.rgb;
  s.normal = p.normal;
  s.vertexNormal = p.vertexNormal;
  s.spec = p.spec;
  s.blockLight = v_light.x;
  s.skyLight = v_light.y;
  s.materialAo = p.occlusion;
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
  float alpha = clamp(p.baseColor.a, 0.0, 1.0);
  vec3 lit = fogged(shade(s, toViewer, visibility, transmittance), v_position, skyColor(-toViewer));
  lit = behindClouds(lit, vec3(0.0), -toViewer, length(v_position));
  o_color = vec4(lit * alpha, alpha);
  o_reactive = 0.0;
}
