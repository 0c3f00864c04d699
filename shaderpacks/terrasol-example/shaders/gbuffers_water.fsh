#version 330 compatibility

#include "/lib/sky.glsl"
#include "/lib/lighting.glsl"

uniform sampler2D gtexture;

in vec2 texcoord;
in vec2 lmcoord;
in vec4 glcolor;
in vec3 normal;
in vec3 viewPosition;
in vec3 worldPosition;
in float water;

uniform float frameTimeCounter;

/* RENDERTARGETS: 0 */
layout(location = 0) out vec4 color;

void main() {
  vec4 albedo = texture(gtexture, texcoord) * glcolor;
  if (albedo.a < 0.01) discard;
  vec3 n = normalize(normal);
  if (water > 0.5) {
    // Ripples: the normal tilts with two crossing waves.
    vec2 p = worldPosition.xz;
    float t = frameTimeCounter * 2.0;
    vec3 tilt = vec3(cos(t + p.x * 0.8 + p.y * 0.6), 0.0, cos(t * 1.3 - p.x * 0.5 + p.y * 0.9)) * 0.12;
    n = normalize(n + mat3(gbufferModelView) * tilt);
  }
  vec3 lit = toLinear(albedo.rgb) * (ambientLight(lmcoord) + directLight() * max(dot(n, lightDirection()), 0.0));
  // The sky's reflection at grazing angles (Schlick, water's F0 0.02).
  vec3 v = normalize(-viewPosition);
  float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
  lit = mix(lit, skyAt(reflect(-v, n)) * lmcoord.y, fresnel);
  color = vec4(lit, max(albedo.a, fresnel));
}
