#version 120

uniform sampler2D gcolor;

varying vec2 texcoord;

void main() {
	vec3 color = texture2D(gcolor, texcoord).rgb;
	gl_FragColor = vec4(color / (color + vec3(0.25f)) * 1.25f, 1.0f);
}
