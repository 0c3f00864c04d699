#version 450 core
// A bloom level: the 2 x 2 texels of the larger one averaged (an odd last row or column repeats its
// edge), so the level holds the same light per unit of screen.

layout(binding = 0) uniform sampler2D u_source;  // linear HDR, twice this size

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  ivec2 last = textureSize(u_source, 0) - 1;
  ivec2 p = ivec2(gl_FragCoord.xy) * 2;
  vec3 sum = texelFetch(u_source, min(p, last), 0).rgb + texelFetch(u_source, min(p + ivec2(1, 0), last), 0).rgb +
             texelFetch(u_source, min(p + ivec2(0, 1), last), 0).rgb +
             texelFetch(u_source, min(p + ivec2(1, 1), last), 0).rgb;
  o_color = vec4(max(sum * 0.25, vec3(0.0)), 1.0);
}
