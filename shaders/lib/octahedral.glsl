// Octahedral normal encoding (the seeds' mapping) with a sign that is never 0: the seeds' sign()
// sends n = (0, 0, -1) to (0, 0), which decodes to +z. core/octahedral.h is the reference;
// tests/gl/glsl_reference_test.cpp runs these against it.

vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

// Unit vector -> [-1, 1]^2.
vec2 octEncode(vec3 n) {
  n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);
  return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * signNotZero(n.xy);
}

vec3 octDecode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
  return normalize(n);  // |n| >= 1/sqrt(3) on the octahedron: never zero
}
