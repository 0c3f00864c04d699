#version 450 core
// The shafts into the scene, added, scaled up bilinearly: scattered light varies slowly across the
// screen, and plain bilinear weights keep this full-screen pass as cheap as a pass can be on a CPU
// rasterizer (weighing the four texels by depth as well cost about three times as much).

#include "lib/bilinear.glsl"

layout(binding = 0) uniform sampler2D u_shafts;  // rgb light; a fraction of the frame's size
uniform vec2 u_scale;                            // the march's size over the scene's

layout(location = OUT_COLOR) out vec4 o_color;

void main() { o_color = vec4(bilinearTexels(u_shafts, gl_FragCoord.xy * u_scale - 0.5), 0.0); }
