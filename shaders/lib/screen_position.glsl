// Where a full-screen pass's pixel looks (fullscreen.vert's v_ndc), camera-relative.

uniform mat4 u_inverseViewProjection;  // camera-relative

in vec2 v_ndc;

vec3 unproject(vec2 ndc, float depth) {
  vec4 p = u_inverseViewProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}

// The unit direction towards the pixel's point on the far plane.
vec3 viewDirection() {
  vec3 far = unproject(v_ndc, 1.0);
  return far / max(length(far), 1e-20);
}
