// The light a surface receives: the sun or moon (the shadow light), the sky's ambient light by the
// sky light level, torches' by the block light level (the lightmap coordinate, 1/32..31/32).

uniform vec3 shadowLightPosition;
uniform float sunAngle;

vec3 lightDirection() { return normalize(shadowLightPosition); }

// The sun's light by day, the moon's by night, fading out as either reaches the horizon.
vec3 directLight() {
  bool day = sunAngle < 0.5;
  float height = sin(fract(sunAngle) * 6.2831853);  // the sun's elevation, sine
  float fade = clamp((day ? height : -height) * 6.0, 0.0, 1.0);
  return (day ? vec3(3.0, 2.85, 2.6) : vec3(0.12, 0.15, 0.25)) * fade;
}

vec3 ambientLight(vec2 lightmap) {
  float sky = clamp((lightmap.y - 1.0 / 32.0) * 16.0 / 15.0, 0.0, 1.0);
  float block = clamp((lightmap.x - 1.0 / 32.0) * 16.0 / 15.0, 0.0, 1.0);
  bool day = sunAngle < 0.5;
  vec3 skyAmbient = (day ? vec3(0.35, 0.45, 0.6) : vec3(0.02, 0.025, 0.05)) * sky * sky;
  vec3 torch = vec3(1.6, 1.1, 0.6) * pow(block, 3.0);
  return skyAmbient + torch + vec3(0.008);
}
