#version 450 core
// Test scene: Lambert sun plus a sky/ground hemisphere ambient, computed in linear light.

#include "lib/color.glsl"

in vec3 v_normal;
in vec3 v_color;

uniform vec3 u_toLight;  // unit vector towards the light

layout(location = OUT_COLOR) out vec4 o_color;

const vec3 kSunColor = vec3(1.0, 0.95, 0.85) * 2.2;
const vec3 kSkyAmbient = vec3(0.30, 0.38, 0.55);
const vec3 kGroundAmbient = vec3(0.12, 0.10, 0.08);

void main() {
  vec3 n = normalize(v_normal);
  vec3 albedo = srgbToLinear(v_color);
  float sun = max(dot(n, u_toLight), 0.0);
  vec3 ambient = mix(kGroundAmbient, kSkyAmbient, n.y * 0.5 + 0.5);
  vec3 radiance = albedo * (kSunColor * sun + ambient);
  o_color = vec4(linearToSrgb(tonemapReinhard(radiance)), 1.0);
}
