#version 330 compatibility
// The sun and moon, bright enough to glow through the tone map.

uniform sampler2D gtexture;
uniform int renderStage;

in vec2 texcoord;
in vec4 glcolor;

/* RENDERTARGETS: 0 */
layout(location = 0) out vec4 color;

void main() {
  vec4 body = texture(gtexture, texcoord) * glcolor;
  float strength = renderStage == MC_RENDER_STAGE_SUN ? 8.0 : 1.0;
  color = vec4(pow(body.rgb, vec3(2.2)) * strength, body.a);
}
