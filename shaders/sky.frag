#version 450 core
// The sky where nothing was drawn: the depth test runs it only on pixels at depth 1.

#include "lib/screen_position.glsl"
#include "lib/sky.glsl"

layout(location = OUT_COLOR) out vec4 o_color;

void main() { o_color = vec4(skyWithStars(viewDirection()), 1.0); }
