#version 450 core
// The sky where nothing was drawn: the depth test runs it only on pixels at depth 1.

#include "lib/screen_position.glsl"
#include "lib/sky.glsl"

layout(location = OUT_COLOR) out vec4 o_color;

const float kFogReach = 4096.0;  // blocks of height fog the sky is seen through

// The clouds lie in front of it; under water, the sky beyond the surface is seen through the water
// above the camera.
void main() {
  vec3 dir = viewDirection();
  vec3 sky = behindClouds(skyWithStars(dir), vec3(0.0), dir, 1e9);  // stars, unlike skyAlong's
  o_color = vec4(mix(heightFogged(sky, dir * kFogReach), u_waterFog, waterFog(dir * 1e4)), 1.0);
}
