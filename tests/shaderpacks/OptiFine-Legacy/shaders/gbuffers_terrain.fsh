#version 120

uniform sampler2D texture;
uniform sampler2D lightmap;

varying vec2 texcoord;
varying vec2 lmcoord;
varying vec4 tint;
varying float foliage;

void main() {
	vec4 color = texture2D(texture, texcoord) * tint * texture2D(lightmap, lmcoord);
/* DRAWBUFFERS:01 */
	gl_FragData[0] = color;
	gl_FragData[1] = vec4(foliage, 0.0f, 0.0f, 1.0f);
}
