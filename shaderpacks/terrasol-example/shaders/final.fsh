#version 330 compatibility
// Exposure and a filmic curve (Narkowicz's ACES fit), then the display's gamma.

#define EXPOSURE 0.6 // [0.4 0.5 0.6 0.8 1.0]

uniform sampler2D colortex0;

in vec2 texcoord;

void main() {
  vec3 x = max(texture(colortex0, texcoord).rgb, 0.0) * EXPOSURE;
  vec3 mapped = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  gl_FragColor = vec4(pow(mapped, vec3(1.0 / 2.2)), 1.0);
}
