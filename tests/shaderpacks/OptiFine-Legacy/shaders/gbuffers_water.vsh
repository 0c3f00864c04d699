#version 120

attribute vec4 mc_Entity;

varying vec2 texcoord;
varying vec2 lmcoord;
varying vec4 tint;
varying float isWater;

void main() {
	texcoord = gl_MultiTexCoord0.st;
	lmcoord = (gl_TextureMatrix[1] * gl_MultiTexCoord1).st;
	tint = gl_Color;
	isWater = float(mc_Entity.x == 10.0);
	gl_Position = ftransform();
}
