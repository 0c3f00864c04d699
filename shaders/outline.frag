#version 450 core
// The targeted block's outline: drawn over the final image, hidden where the G-buffer has something
// nearer (the box is grown a little, so the block's own visible edges stay in front of its faces).

layout(binding = 0) uniform sampler2D u_depth;
uniform vec2 u_depthScale;  // depth texels per target pixel (below 1 at a render scale)

out vec4 o_color;

void main() {
  float scene = texelFetch(u_depth, ivec2(gl_FragCoord.xy * u_depthScale), 0).r;
  if (gl_FragCoord.z > scene) discard;
  o_color = vec4(0.0, 0.0, 0.0, 0.4);  // Minecraft's: black at 40 %
}
