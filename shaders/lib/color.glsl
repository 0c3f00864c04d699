// Colour-space conversions (exact piecewise sRGB, not a 2.2 power) and tonemapping.

vec3 srgbToLinear(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Maps [0, inf) to [0, 1); max() keeps negative or NaN-free inputs from dividing by zero.
vec3 tonemapReinhard(vec3 c) {
  c = max(c, vec3(0.0));
  return c / (1.0 + c);
}
