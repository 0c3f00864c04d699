#version 450 core
// Light shafts, marched at a fraction of the frame's size: along each pixel's view ray, up to its
// surface or the shadow map's reach, the sunlight the height fog's medium scatters towards the camera
// wherever the map sees the sun (Henyey-Greenstein, forward-peaked), dimmed by the medium on its way.
// Samples start at a per-pixel offset (interleaved gradient noise, moved each frame under TAA, whose
// history then averages it). Out: the light added.

#include "lib/screen_position.glsl"
#include "lib/sky.glsl"
#include "lib/shadow.glsl"

layout(binding = GB_DEPTH_UNIT) uniform sampler2D g_depth;
uniform vec3 u_toLight;
uniform vec3 u_lightColor;
uniform float u_shaftDistance;  // blocks: the shadow map's reach
uniform vec2 u_noiseOffset;     // moves the samples' start each frame

layout(location = OUT_COLOR) out vec4 o_shafts;

const float kForward = 0.6;  // Henyey-Greenstein's g: haze scatters mostly forwards

// The map's lit fraction at a point in the air: one tap, no normal to offset along.
float litAt(vec3 position) {
  int cascade = cascadeOf(position);
  vec4 p = u_shadowMatrices[cascade] * vec4(position, 1.0);
  if (any(greaterThan(abs(p.xyz), vec3(1.0)))) return 1.0;
  float bias = 0.05 / u_shadowDepthRanges[cascade];
  return shadowTap(warpShadow(p.xy) * 0.5 + 0.5, float(cascade), p.z * 0.5 + 0.5 - bias, vec2(0.0));
}

void main() {
  ivec2 size = textureSize(g_depth, 0);
  ivec2 pixel = clamp(ivec2((v_ndc * 0.5 + 0.5) * vec2(size)), ivec2(0), size - 1);
  float depth = texelFetch(g_depth, pixel, 0).r;
  vec3 dir = viewDirection();
  float distance = depth < 1.0 ? min(length(unproject(v_ndc, depth)), u_shaftDistance) : u_shaftDistance;
  if (!u_shadowLive) {
    o_shafts = vec4(0.0);
    return;
  }
  float step = distance / float(SHAFT_SAMPLES);
  float t = step * interleavedGradientNoise(gl_FragCoord.xy + u_noiseOffset);
  float transmittance = 1.0, scattered = 0.0;
  for (int i = 0; i < SHAFT_SAMPLES; ++i) {
    vec3 p = dir * t;
    float sigma = heightFogDensity(p);
    float through = exp(-sigma * step);
    // The light scattered in this step, of what is still left after the medium before it.
    scattered += litAt(p) * transmittance * (1.0 - through);
    transmittance *= through;
    t += step;
  }
  float c = dot(dir, u_toLight);
  float g2 = kForward * kForward;
  float m = max(1.0 + g2 - 2.0 * kForward * c, 1e-4);
  float phase = (1.0 - g2) / (m * sqrt(m));  // 1 on average over the sphere
  o_shafts = vec4(u_lightColor * (scattered * phase), 1.0);
}
