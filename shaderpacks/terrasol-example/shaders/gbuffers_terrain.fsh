#version 330 compatibility

uniform sampler2D gtexture;
uniform sampler2D specular;

in vec2 texcoord;
in vec2 lmcoord;
in vec4 glcolor;
in vec3 normal;

/* RENDERTARGETS: 0,1,2,3 */
layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 light;
layout(location = 2) out vec4 encodedNormal;
layout(location = 3) out vec4 material;

void main() {
  albedo = texture(gtexture, texcoord) * glcolor;
  if (albedo.a < 0.1) discard;
  light = vec4(lmcoord, 0.0, 1.0);
  encodedNormal = vec4(normalize(normal) * 0.5 + 0.5, 1.0);
  material = texture(specular, texcoord);
}
