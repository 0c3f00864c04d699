#version 330 compatibility
// Water, glass and ice, lit forward over the lit scene. Water (block.properties id 1) ripples: its
// surface rises and falls and its normal sways with the time, so two moments draw it apart.

in vec4 mc_Entity;

uniform mat4 gbufferModelViewInverse;
uniform vec3 cameraPosition;
uniform float frameTimeCounter;

out vec2 texcoord;
out vec2 lmcoord;
out vec4 glcolor;
out vec3 normal;
out vec3 viewPosition;
out vec3 worldPosition;
out float water;

void main() {
  texcoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy;
  lmcoord = (gl_TextureMatrix[1] * gl_MultiTexCoord1).xy;
  glcolor = gl_Color;
  normal = normalize(gl_NormalMatrix * gl_Normal);
  vec4 position = gl_ModelViewMatrix * gl_Vertex;
  worldPosition = (gbufferModelViewInverse * position).xyz + cameraPosition;
  water = mc_Entity.x == 1.0 ? 1.0 : 0.0;
  if (water > 0.5) {
    float wave = sin(frameTimeCounter * 2.0 + worldPosition.x * 0.8 + worldPosition.z * 0.6) * 0.05 - 0.05;
    position += gl_ModelViewMatrix * vec4(0.0, wave, 0.0, 0.0);
  }
  viewPosition = position.xyz;
  gl_Position = gl_ProjectionMatrix * position;
}
