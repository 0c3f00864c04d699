#version 120

// A soft glow from a coarser mip level of the scene, weighted by a C-style array.
const bool gcolorMipmapEnabled = true;
const float kWeights[5] = {0.1f, 0.2f, 0.4f, 0.2f, 0.1f};

uniform sampler2D gcolor;
uniform sampler2D gdepth;
uniform float viewWidth;

varying vec2 texcoord;

void main() {
	vec3 glow = vec3(0.0f);
	for (int i = 0; i < 5; i++) {
		vec2 offset = vec2(float(i - 2) * 8.0f / viewWidth, 0.0f);
		glow += texture2DLod(gcolor, texcoord + offset, 3.0f).rgb * kWeights[i];
	}
	vec3 color = texture2D(gcolor, texcoord).rgb;
	// Foliage (gdepth's red, from the terrain program) a touch warmer.
	color *= mix(vec3(1.0f), vec3(1.05f, 1.0f, 0.9f), texture2D(gdepth, texcoord).r);
/* DRAWBUFFERS:0 */
	gl_FragData[0] = vec4(color + glow * 0.25f, 1.0f);
}
