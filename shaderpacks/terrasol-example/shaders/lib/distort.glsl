// The shadow map's warp: texels crowd near the player, where shadows are looked at closely, and thin
// out towards the map's edge (the seeds' "shadow distortion"). Shared by the shadow pass, which draws
// the warped map, and the lighting, which looks it up.

#define SHADOW_DISTORT 0.10 // How strongly the map is warped towards the player [0.05 0.10 0.15 0.20]

const int shadowMapResolution = 1024; // [1024 2048 4096]
const float shadowDistance = 64.0;    // [48.0 64.0 96.0 128.0]

// Shadow clip space (xy in -1..1) to the warped map; z is halved so far casters stay inside.
vec3 distort(vec3 position) {
  float factor = length(position.xy) + SHADOW_DISTORT;
  return vec3(position.xy / factor, position.z * 0.5);
}

// How many blocks a texel covers at `position` (clip space), relative to the unwarped map: the
// derivative of the warp, inverted. The bias grows with it.
float texelScale(vec3 position) {
  float factor = length(position.xy) + SHADOW_DISTORT;
  return factor * factor / SHADOW_DISTORT;
}
