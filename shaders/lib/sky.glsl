// The sky seen along a direction: a gradient by time of day (scaled by SKY_RADIANCE, core/day_cycle.h),
// the sun and moon discs, and stars.

uniform vec3 u_skyZenith;
uniform vec3 u_skyHorizon;
uniform vec3 u_toSun;
uniform vec3 u_toMoon;
uniform vec3 u_sunColor;
uniform vec3 u_moonColor;
uniform float u_starVisibility;

const float kSunCos = 0.99966;   // ~1.5 degrees radius, a little larger than the real sun, like vanilla's
const float kMoonCos = 0.99978;

float hash13(vec3 p) {
  p = fract(p * 0.1031);
  p += dot(p, p.zyx + 31.32);
  return fract((p.x + p.y) * p.z);
}

vec3 skyColor(vec3 dir) {
  float up = dir.y;
  // Below the horizon the haze stays near the horizon's colour, so fog at the world's edge blends in.
  vec3 color = SKY_RADIANCE * (up >= 0.0 ? mix(u_skyHorizon, u_skyZenith, sqrt(up))
                                         : mix(u_skyHorizon, u_skyHorizon * 0.7, min(-up * 2.0, 1.0)));
  float toSun = dot(dir, u_toSun);
  float glow = max(toSun, 0.0);
  glow *= glow;
  glow *= glow;
  glow *= glow;  // ^8
  color += u_sunColor * (0.5 * glow * glow * glow);  // glow around the sun: toSun^24, without pow()
  color += u_sunColor * 20.0 * smoothstep(kSunCos - 0.00006, kSunCos, toSun);
  color += u_moonColor * 10.0 * smoothstep(kMoonCos - 0.00004, kMoonCos, dot(dir, u_toMoon));
  return color;
}

// Stars, added where the sky itself shows: fog is the sky's colour behind a surface, and stars there
// would glitter on distant hills (and cost every lit pixel, since llvmpipe runs both sides of a branch).
vec3 skyWithStars(vec3 dir) {
  vec3 color = skyColor(dir);
  float up = dir.y;
  if (u_starVisibility > 0.0 && up > 0.0) {
    vec3 cell = floor(dir * 300.0);
    float star = step(0.9985, hash13(cell));
    color += vec3(star * u_starVisibility * smoothstep(0.0, 0.2, up) * 3.0);
  }
  return color;
}

uniform vec2 u_fogRange;  // start, end (horizontal blocks from the camera)
uniform bool u_underWater;  // the camera is under a liquid's surface
uniform float u_waterTop;   // its height above the camera (blocks)
uniform vec3 u_waterFog;    // the colour the depths fade to (linear)

// Under water, how much of the way to `position` (camera-relative) fades into the water's colour:
// the part of it below the surface, one e-fold every 10 blocks (0 above water).
float waterFog(vec3 position) {
  if (!u_underWater) return 0.0;
  float path = length(position);
  if (position.y > u_waterTop) path *= u_waterTop / position.y;  // the rest lies above the surface
  return 1.0 - exp(-path / 10.0);
}

// Height fog (render.fog, with HEIGHT_FOG): a medium whose extinction falls off exponentially with
// height, scattering the sky's light (dimmed as the camera's sky light is; the sun's is the shafts').
uniform vec2 u_heightFog;         // extinction per block at the camera's height; blocks per e-fold
uniform vec3 u_heightFogColour;   // the light it scatters towards the camera (linear)

// Its extinction per block at `position` (camera-relative); the exponent capped, as on the CPU.
float heightFogDensity(vec3 position) {
  return u_heightFog.x * exp(-clamp(position.y / u_heightFog.y, -20.0, 80.0));
}

// Its optical depth from the camera to `position`: the density integrated along the straight path,
// L x (1 - e^-k) / k for a rise of k e-folds (its series near k = 0, where the quotient is 0 / 0).
float heightFogDepth(vec3 position) {
  float k = clamp(position.y / u_heightFog.y, -20.0, 80.0);
  float integral = abs(k) < 1e-3 ? 1.0 - 0.5 * k : (1.0 - exp(-k)) / k;
  return u_heightFog.x * length(position) * integral;
}

// `color` seen through the height fog from the camera to `position` (unchanged without HEIGHT_FOG).
vec3 heightFogged(vec3 color, vec3 position) {
#ifdef HEIGHT_FOG
  return mix(u_heightFogColour, color, exp(-heightFogDepth(position)));
#else
  return color;
#endif
}

// Distant surfaces fade into the sky behind them (`sky`: skyColor(viewDir)), so the world's edge
// never shows; the height fog lies over them; under water, they fade into the water's colour.
vec3 fogged(vec3 color, vec3 position, vec3 sky) {
  float fog = smoothstep(u_fogRange.x, u_fogRange.y, length(position.xz));
  return mix(heightFogged(mix(color, sky, fog), position), u_waterFog, waterFog(position));
}

// Light added on top of a surface's (a reflection), faded as the surface is.
vec3 foggedLight(vec3 light, vec3 position) {
  float fog = smoothstep(u_fogRange.x, u_fogRange.y, length(position.xz));
  float through = (1.0 - fog) * (1.0 - waterFog(position));
#ifdef HEIGHT_FOG
  through *= exp(-heightFogDepth(position));
#endif
  return light * through;
}

#include "lib/clouds.glsl"
