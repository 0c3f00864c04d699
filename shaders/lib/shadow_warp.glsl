// The shadow map's warp, the one function both the shadow pass and the lookup use, so the two can
// never disagree. p is the unwarped map position in [-1, 1]^2; the warp keeps that square and crowds
// texels towards the centre (the camera).

uniform int u_shadowWarp;             // 0 none, 1 square (per axis, the seeds'), 2 radial (Luanti's)
uniform float u_shadowWarpStrength;   // [0, 1)

vec2 warpShadow(vec2 p) {
  float a = u_shadowWarpStrength;
  if (u_shadowWarp == 1) return p / mix(vec2(1.0), abs(p), a);
  if (u_shadowWarp == 2) return p / (length(p) * a + 1.0 - a);
  return p;
}

// How much the warp magnifies at p, in its least magnified direction: a warped texel there covers
// 1 / warpScale(p) unwarped texels.
float warpScale(vec2 p) {
  float a = u_shadowWarpStrength;
  if (u_shadowWarp == 1) {
    vec2 m = mix(vec2(1.0), abs(p), a);
    vec2 d = (1.0 - a) / (m * m);
    return min(d.x, d.y);
  }
  if (u_shadowWarp == 2) {
    float m = length(p) * a + 1.0 - a;
    return (1.0 - a) / (m * m);
  }
  return 1.0;
}
