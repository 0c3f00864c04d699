// The distance along the view to the surface a depth buffer value (0..1) stands for, from the
// perspective projection's near and far planes.

uniform vec2 u_nearFar;

float viewDepth(float depth) {
  float n = u_nearFar.x, f = u_nearFar.y;
  return 2.0 * n * f / max(f + n - (depth * 2.0 - 1.0) * (f - n), 1e-6);
}
