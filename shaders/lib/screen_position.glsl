// Where a full-screen pass's pixel looks (fullscreen.vert's v_ndc), camera-relative.

#include "lib/unproject.glsl"

in vec2 v_ndc;

// The unit direction towards the pixel's point on the far plane.
vec3 viewDirection() {
  vec3 far = unproject(v_ndc, 1.0);
  return far / max(length(far), 1e-20);
}
