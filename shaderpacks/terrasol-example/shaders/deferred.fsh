#version 330 compatibility
// Deferred lighting of everything opaque: the sun's light through the warped shadow map, filtered
// (PCF), LabPBR's specular, the sky's and torches' light by level, emission; fog towards the far
// distance. Writes the lit scene (linear HDR) and the shadow term, which Terrasol's --report compares
// with the ray-traced truth (shaders.properties: terrasol.report.*).

#include "/lib/distort.glsl"
#include "/lib/sky.glsl"
#include "/lib/lighting.glsl"

#define PCF_RADIUS 1 // Taps each way from the centre: (2r+1)^2 comparisons [0 1 2]

uniform sampler2D colortex0; // albedo; the sky where nothing was drawn
uniform sampler2D colortex1; // lightmap coordinate
uniform sampler2D colortex2; // normal, view space, encoded
uniform sampler2D colortex3; // LabPBR specular
uniform sampler2D depthtex0;
uniform sampler2DShadow shadowtex1; // opaque casters, compared in hardware
uniform mat4 gbufferProjectionInverse;
uniform mat4 gbufferModelViewInverse;
uniform mat4 shadowModelView;
uniform mat4 shadowProjection;
uniform float far;

const bool shadowHardwareFiltering = true;
/* Buffer formats (read by the loader; GLSL does not know their names):
const int colortex0Format = RGBA16F;
const int colortex2Format = RGBA16F;
const int colortex4Format = R8;
*/

in vec2 texcoord;

/* RENDERTARGETS: 0,4 */
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 shadowTerm;

// The fraction of (2r+1)^2 taps around `position` (player space) that the sun reaches.
float sunVisibility(vec3 position, vec3 playerNormal) {
  vec4 clip = shadowProjection * (shadowModelView * vec4(position, 1.0));
  // Normal offset: a texel's worth (grown by the warp) off the surface, so it does not shadow itself.
  float texel = 2.0 * shadowDistance / float(shadowMapResolution);
  position += playerNormal * texel * texelScale(clip.xyz) * 1.5;
  clip = shadowProjection * (shadowModelView * vec4(position, 1.0));
  vec3 map = distort(clip.xyz) * 0.5 + 0.5;
  if (any(lessThan(map.xy, vec2(0.0))) || any(greaterThan(map.xy, vec2(1.0)))) return 1.0;
  float lit = 0.0;
  float step = 1.0 / float(shadowMapResolution);
  for (int y = -PCF_RADIUS; y <= PCF_RADIUS; ++y)
    for (int x = -PCF_RADIUS; x <= PCF_RADIUS; ++x)
      lit += texture(shadowtex1, vec3(map.xy + vec2(x, y) * step, map.z));
  return lit / float((2 * PCF_RADIUS + 1) * (2 * PCF_RADIUS + 1));
}

void main() {
  float depth = texture(depthtex0, texcoord).r;
  vec4 albedo = texture(colortex0, texcoord);
  if (depth >= 1.0) { // the sky, as drawn
    color = albedo;
    shadowTerm = vec4(1.0);
    return;
  }
  vec4 ndc = vec4(texcoord, depth, 1.0) * 2.0 - 1.0;
  vec4 view = gbufferProjectionInverse * ndc;
  vec3 viewPosition = view.xyz / view.w;
  vec3 position = (gbufferModelViewInverse * vec4(viewPosition, 1.0)).xyz;
  vec3 n = normalize(texture(colortex2, texcoord).xyz * 2.0 - 1.0);
  vec3 playerNormal = mat3(gbufferModelViewInverse) * n;
  vec2 lightmap = texture(colortex1, texcoord).xy;
  vec4 specular = texture(colortex3, texcoord);

  vec3 base = toLinear(albedo.rgb);
  vec3 l = lightDirection();
  float facing = max(dot(n, l), 0.0);
  float visible = facing > 0.0 ? sunVisibility(position, playerNormal) : 0.0;

  // LabPBR: red is perceptual smoothness, green F0 (metals from 230 on tint their reflection).
  float smoothness = specular.r;
  float roughness = max((1.0 - smoothness) * (1.0 - smoothness), 0.02);
  bool metal = specular.g * 255.0 > 229.5;
  vec3 f0 = metal ? base : vec3(specular.g);
  vec3 v = normalize(-viewPosition);
  vec3 h = normalize(l + v);
  float shininess = 2.0 / (roughness * roughness) - 2.0;
  vec3 fresnel = f0 + (1.0 - f0) * pow(1.0 - max(dot(h, v), 0.0), 5.0);
  vec3 highlight = fresnel * (shininess + 8.0) / 25.1327 * pow(max(dot(n, h), 0.0), shininess);
  vec3 diffuse = metal ? vec3(0.0) : base;
  vec3 lit = (diffuse + highlight) * directLight() * facing * visible + diffuse * ambientLight(lightmap);
  // Emission: alpha 0..254 of 255 (255 means none).
  float emission = specular.a * 255.0 < 254.5 ? specular.a : 0.0;
  lit += base * emission * 4.0;

  float fog = smoothstep(0.8 * far, far, length(viewPosition));
  color = vec4(mix(lit, skyAt(normalize(viewPosition)), fog), 1.0);
  shadowTerm = vec4(visible, 0.0, 0.0, 1.0);
}
