#version 120

attribute vec2 mc_Entity;

uniform float frameTimeCounter;

varying vec2 texcoord;
varying vec2 lmcoord;
varying vec4 tint;
varying float foliage;

void main() {
	texcoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
	lmcoord = (gl_TextureMatrix[1] * gl_MultiTexCoord1).st;
	tint = gl_Color;
	foliage = mc_Entity.x == 11.0f || mc_Entity.x == 12.0f ? 1.0f : 0.0f;
	vec4 position = gl_Vertex;
	// Leaves and plants sway a little.
	if (foliage > 0.5f) position.x += sin(frameTimeCounter * 1.5f + position.z) * 0.03f;
	gl_Position = gl_ModelViewProjectionMatrix * position;
}
