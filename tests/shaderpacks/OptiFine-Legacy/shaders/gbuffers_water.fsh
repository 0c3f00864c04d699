#version 120

uniform sampler2D texture;
uniform sampler2D lightmap;

varying vec2 texcoord;
varying vec2 lmcoord;
varying vec4 tint;
varying float isWater;

void main() {
	vec4 color = texture2D(texture, texcoord) * tint * texture2D(lightmap, lmcoord);
	// Water a deeper blue than the pack draws it; glass as it is.
	color.rgb = mix(color.rgb, color.rgb * vec3(0.6, 0.8, 1.2), isWater);
/* DRAWBUFFERS:0 */
	gl_FragData[0] = color;
}
