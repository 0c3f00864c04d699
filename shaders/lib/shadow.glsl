// Shadow map lookup: normal offset and slope-scaled depth bias sized to the local (warped) texel,
// then PCF with hardware depth comparison. Outside the map or beyond its depth range counts as lit.
// The map is a layer per cascade: one warped layer, or up to 4 unwarped cascades growing outwards
// from the camera, of which the smallest that holds the point is used.

#include "lib/shadow_warp.glsl"

layout(binding = UNIT_SHADOW_MAP) uniform sampler2DArrayShadow u_shadowMap;  // opaque and cutout casters
// Translucent casters (water, glass): the colour light keeps through the nearest one, and its depth in
// alpha (1 where there is none). Nearest texels: one fetch, no filtering.
layout(binding = UNIT_TRANSMITTANCE) uniform sampler2DArray u_transmittance;
uniform int u_cascades;                   // layers in use, 1..SHADOW_MAX_CASCADES
uniform mat4 u_shadowMatrices[SHADOW_MAX_CASCADES];  // camera-relative world -> light clip space (unwarped)
uniform float u_shadowTexelWorlds[SHADOW_MAX_CASCADES];  // blocks per texel of each layer, unwarped
uniform float u_shadowDepthRanges[SHADOW_MAX_CASCADES];  // blocks from each layer's near to far plane
uniform float u_shadowResolution;  // texels per side
// PCF_DISK: the 16-tap rotated Poisson disk; PCF_GRID_SIDE S: S^2 grid taps; PCF_TENT: four bilinear
// taps; none: one tap.
uniform float u_pcfRadius;         // texels, or blocks with u_pcfRadiusInBlocks
uniform bool u_pcfRadiusInBlocks;
uniform bool u_shadowLive;         // false when no pass ran this frame (no light above the horizon)

const vec2 kPoisson[16] = vec2[16](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

// Jimenez's interleaved gradient noise: a per-pixel angle that hides the disk's pattern.
float interleavedGradientNoise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

float shadowTap(vec2 uv, float layer, float depth, vec2 offsetTexels) {
  return texture(u_shadowMap, vec4(uv + offsetTexels / u_shadowResolution, layer, depth));
}

// The smallest cascade sure to hold the point: one whose half-width exceeds the point's distance from
// the camera (light-space |xy| <= that distance), with a margin for the PCF taps and the offset. Chosen
// by distance, not by map position, so the choice does not change when the maps step by a texel.
int cascadeOf(vec3 position) {
  float distance = length(position);
  for (int i = 0; i < u_cascades - 1; ++i) {
    if (distance < 0.9 * u_shadowTexelWorlds[i] * u_shadowResolution * 0.5) return i;
  }
  return u_cascades - 1;
}

// Where a surface point looks up the maps: offset along the normal and biased by the local texel.
struct ShadowLookup {
  bool inside;  // false outside the map or its depth range: lit
  vec2 uv;
  float layer;
  float depth;
  float radius;  // PCF radius in texels of this layer, here
};

// `position` camera-relative, `vertexNormal` unit, `cosTheta` = dot(vertexNormal, toLight) > 0.
ShadowLookup shadowLookup(vec3 position, vec3 vertexNormal, float cosTheta) {
  int cascade = cascadeOf(position);
  mat4 toLight = u_shadowMatrices[cascade];
  vec4 unshifted = toLight * vec4(position, 1.0);
  // One warped texel here, in blocks; clamped where a strong warp makes the edge texels huge.
  float texel = min(u_shadowTexelWorlds[cascade] / max(warpScale(unshifted.xy), 1e-3), 4.0);
  float c = clamp(cosTheta, 0.0, 1.0);
  float sinTheta = sqrt(1.0 - c * c);
  float tanTheta = min(sinTheta / max(c, 1e-3), 10.0);  // grazing light: tan -> infinity, clamped
  // A radius in blocks covers fewer texels where texels are large (far from the camera in a warped map).
  float radius = u_pcfRadiusInBlocks ? min(u_pcfRadius / texel, 32.0) : u_pcfRadius;
#if defined(PCF_DISK) || defined(PCF_GRID_SIDE) || defined(PCF_TENT)
  float spread = 1.0 + radius;
#else
  float spread = 1.0;
#endif
  vec3 offset = vertexNormal * texel * spread * (0.35 + 0.65 * sinTheta);
  vec4 p = toLight * vec4(position + offset, 1.0);
  ShadowLookup l;
  l.inside = all(lessThanEqual(abs(p.xyz), vec3(1.0)));
  l.uv = warpShadow(p.xy) * 0.5 + 0.5;
  l.layer = float(cascade);
  float bias = (texel * spread * 0.5 * tanTheta + 0.02) / u_shadowDepthRanges[cascade];
  l.depth = p.z * 0.5 + 0.5 - bias;
  l.radius = radius;
  return l;
}

// The lit fraction from opaque and cutout casters, PCF-filtered: 1 = fully lit.
float shadowVisibility(ShadowLookup l, vec2 pixel) {
  if (!l.inside) return 1.0;
#if defined(PCF_DISK)
  float angle = 6.2831853 * interleavedGradientNoise(pixel);
  mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
  float lit = 0.0;
  for (int i = 0; i < 16; ++i) lit += shadowTap(l.uv, l.layer, l.depth, rotation * kPoisson[i] * l.radius);
  return lit / 16.0;
#elif defined(PCF_TENT)
  // Four bilinear compares half the radius apart: at a radius of one texel, the 3x3 tent (1 2 1)^2 / 16
  // of nine point taps, for the price of four.
  vec2 h = vec2(0.5 * l.radius);
  return 0.25 * (shadowTap(l.uv, l.layer, l.depth, -h) + shadowTap(l.uv, l.layer, l.depth, vec2(h.x, -h.y)) +
                 shadowTap(l.uv, l.layer, l.depth, vec2(-h.x, h.y)) + shadowTap(l.uv, l.layer, l.depth, h));
#elif defined(PCF_GRID_SIDE)
  const int n = PCF_GRID_SIDE / 2;
  float step = l.radius / float(n);
  float lit = 0.0;
  for (int y = -n; y <= n; ++y)
    for (int x = -n; x <= n; ++x) lit += shadowTap(l.uv, l.layer, l.depth, vec2(x, y) * step);
  return lit / float(PCF_GRID_SIDE * PCF_GRID_SIDE);
#else
  return shadowTap(l.uv, l.layer, l.depth, vec2(0.0));
#endif
}

// The colour the light keeps after the nearest translucent caster above the point (white if none).
vec3 shadowTransmittance(ShadowLookup l) {
  if (!l.inside) return vec3(1.0);
  vec4 caster = texture(u_transmittance, vec3(l.uv, l.layer));
  return l.depth <= caster.a ? vec3(1.0) : caster.rgb;  // the same test as the opaque map's LEQUAL
}
