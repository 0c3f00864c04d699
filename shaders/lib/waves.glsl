// Water's moving surface (render.water.waves), shared by the translucent pass and the reflection
// pass's march from water.

uniform float u_waveTime;    // seconds of world time (wrapped at an hour)
uniform vec3 u_waveOrigin;   // the camera's world position wrapped at 256 blocks

// The normal of water's moving surface: four summed waves (direction, wavelength, height, speed),
// their slopes only (the geometry stays flat), so the surface ripples in light and reflections.
vec3 waveNormal(vec3 position) {
  vec2 p = position.xz + u_waveOrigin.xz;
  const vec4 waves[4] = vec4[4](vec4(0.96, 0.28, 6.0, 0.020), vec4(-0.55, 0.84, 3.7, 0.014),
                                vec4(0.31, -0.95, 2.3, 0.009), vec4(-0.88, -0.47, 1.3, 0.005));
  vec2 slope = vec2(0.0);
  for (int i = 0; i < 4; ++i) {
    float k = 6.2831853 / waves[i].z;
    float phase = k * dot(waves[i].xy, p) - sqrt(9.81 * k) * u_waveTime;
    slope += waves[i].xy * (waves[i].w * k * cos(phase));
  }
  return normalize(vec3(-slope.x, 1.0, -slope.y));
}
