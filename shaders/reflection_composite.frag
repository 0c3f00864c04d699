#version 450 core
// Adds the reflections (reflection.frag, at its own resolution, filtered up) to the lit scene. Drawn
// at depth 1 against the scene's depth with GL_GREATER: only where something was drawn.

layout(binding = UNIT_REFLECTION) uniform sampler2D u_reflection;

in vec2 v_ndc;

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  o_color = vec4(texture(u_reflection, v_ndc * 0.5 + 0.5).rgb, 0.0);  // blended: rgb added, alpha kept
}
