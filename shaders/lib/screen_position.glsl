// Where a full-screen pass's pixel looks (fullscreen.vert's v_ndc), camera-relative.

#include "lib/unproject.glsl"

in vec2 v_ndc;

// The unit direction towards the pixel's point on the far plane.
vec3 viewDirection() {
  vec3 far = unproject(v_ndc, 1.0);
  return far / max(length(far), 1e-20);
}

// The pixel of a `size` image under this pass's pixel, drawn at `targetSize`: the one holding its
// centre, in integer arithmetic. A float `uv * size` lands exactly on a pixel border whenever the
// scale is an even ratio (a quarter: 4x + 2.0) and rounds either way; a normal-mapped surface then
// sends the ray from a neighbour the reports cannot know.
ivec2 pixelUnder(ivec2 size, ivec2 targetSize) {
  ivec2 twice = 2 * ivec2(gl_FragCoord.xy) + 1;
  return clamp(twice * size / (2 * targetSize), ivec2(0), size - 1);
}
