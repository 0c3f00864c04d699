// A camera-relative point from normalised device coordinates and depth (0..1).

uniform mat4 u_inverseViewProjection;  // camera-relative

vec3 unproject(vec2 ndc, float depth) {
  vec4 p = u_inverseViewProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}
