#version 450 core
// Temporal anti-aliasing and upscaling. Each target pixel gathers this frame's 3 x 3 nearest scene
// samples, each placed where the jitter put it and weighted by its distance from the pixel (which
// undoes the jitter and, at a render scale, reconstructs the larger image), then blends that with the
// last frame's result found by reprojection: the nearest surface of the neighbourhood (so edges move
// with the foreground) carried through the camera's motion into the last frame's view. The history is
// clipped to the spread of this frame's samples in YCoCg, in a compressed (perceptual) range, so a
// colour the scene no longer shows cannot linger, and dropped where the surface it saw is not the one
// seen now (the distance it stored disagrees: a disocclusion) or it falls off the screen. Where the
// translucent pass marked water (the reactive mask: it changes by itself, so its history is a blur in
// time), this frame counts for half at least. Whole-texel fetches only: filtered lookups cost far
// more on llvmpipe.

#include "lib/compressed_range.glsl"
#include "lib/unproject.glsl"

layout(binding = 0) uniform sampler2D u_scene;    // linear HDR at the scene's size, jittered
layout(binding = 1) uniform sampler2D u_depth;    // the scene's depth
layout(binding = 2) uniform sampler2D u_history;  // last frame's output: rgb colour, a distance
layout(binding = 3) uniform sampler2D u_reactiveMask;  // the scene's: 1 where it changes by itself
uniform bool u_reactive;       // the translucent pass drew the mask this frame
uniform mat4 u_reprojection;  // the last frame's camera-relative view-projection, unjittered
uniform vec3 u_cameraMotion;  // this frame's camera minus the last frame's
uniform vec2 u_jitter;        // this frame's offset, in scene pixels
uniform vec2 u_sceneScale;    // scene pixels per target pixel
uniform bool u_historyValid;

layout(location = OUT_COLOR) out vec4 o_color;

const float kBlend = 0.1;             // this frame's share where a sample falls right on the pixel
const float kMinBlend = 0.04;         // and where none does: a ghost fades within a few dozen frames
const float kClipSigma = 1.25;        // the box's half-size in standard deviations of the samples,
const float kClipSigmaMoving = 0.75;  // and at kFastMotion target pixels a frame or more,
const float kBlendMoving = 0.3;       // where this frame's share is
const float kFastMotion = 8.0;
const float kBlendReactive = 0.5;    // this frame's share at least, on water (the reactive mask)
const float kSkyDistance = 60000.0;   // stored for the sky (within half-float range)
const float kDistanceTolerance = 0.1; // relative: a stored distance further off is another surface

vec3 toYCoCg(vec3 c) {
  return vec3(dot(c, vec3(0.25, 0.5, 0.25)), dot(c, vec3(0.5, 0.0, -0.5)), dot(c, vec3(-0.25, 0.5, -0.25)));
}
vec3 fromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// `h` moved toward the box's centre until it lies inside (clipping keeps its hue, clamping would not).
vec3 clipToBox(vec3 h, vec3 centre, vec3 extent) {
  vec3 v = h - centre;
  vec3 a = abs(v) / max(extent, vec3(1e-5));
  float outside = max(a.x, max(a.y, a.z));
  return outside > 1.0 ? centre + v / outside : h;
}

// The history's colour at target pixel position `p`, Catmull-Rom filtered from five bilinear taps
// (a bilinear history blurs a little more with every reprojection; this one keeps edges).
vec3 historyColour(vec2 p) {
  vec2 size = vec2(textureSize(u_history, 0));
  vec2 centre = floor(p - 0.5) + 0.5;
  vec2 f = p - centre;
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 w12 = w1 + w2;
  vec2 at0 = (centre - 1.0) / size, at3 = (centre + 2.0) / size, at12 = (centre + w2 / w12) / size;
  vec3 c = texture(u_history, vec2(at12.x, at0.y)).rgb * (w12.x * w0.y) +
           texture(u_history, vec2(at0.x, at12.y)).rgb * (w0.x * w12.y) +
           texture(u_history, at12).rgb * (w12.x * w12.y) +
           texture(u_history, vec2(at3.x, at12.y)).rgb * (w3.x * w12.y) +
           texture(u_history, vec2(at12.x, at3.y)).rgb * (w12.x * w3.y);
  float total = w12.x * w0.y + w0.x * w12.y + w12.x * w12.y + w3.x * w12.y + w12.x * w3.y;
  return max(c / total, vec3(0.0));
}

ivec2 g_lastTexel;

void gather(ivec2 centre, ivec2 step, vec2 offset, inout vec3 sum, inout float weights, inout vec3 m1,
            inout vec3 m2) {
  ivec2 t = clamp(centre + step, ivec2(0), g_lastTexel);
  vec3 c = compress(max(texelFetch(u_scene, t, 0).rgb, vec3(0.0)));
  vec2 d = (offset + vec2(step)) / u_sceneScale;  // in target pixels
  float w = exp(-2.29 * dot(d, d));  // a Gaussian fit of the Blackman-Harris window
  sum += c * w;
  weights += w;
  vec3 ycocg = toYCoCg(c);
  m1 += ycocg;
  m2 += ycocg * ycocg;
}

void main() {
  ivec2 sceneSize = textureSize(u_scene, 0);
  g_lastTexel = sceneSize - 1;
  // This pixel's centre in unjittered scene pixels; texel t's sample lies at t + 0.5 - jitter.
  vec2 at = gl_FragCoord.xy * u_sceneScale;
  ivec2 centre = ivec2(floor(at + u_jitter));
  vec2 offset = vec2(centre) + 0.5 - u_jitter - at;  // the centre sample's place from the pixel's

  // The centre sample and its four neighbours: their weighted mean is this frame's estimate, their
  // spread the box the history must fall in, their nearest depth the surface to reproject.
  vec3 sum = vec3(0.0), m1 = vec3(0.0), m2 = vec3(0.0);
  float weights = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) gather(centre, ivec2(x, y), offset, sum, weights, m1, m2);
  // The nearest depth of the centre and its four neighbours, so an edge's pixels follow the
  // foreground and keep their history as the jitter moves the edge across them.
  float nearestDepth = 1.0;
  for (int k = 0; k < 5; ++k) {
    ivec2 step = k == 0 ? ivec2(0) : k == 1 ? ivec2(1, 0) : k == 2 ? ivec2(-1, 0) : k == 3 ? ivec2(0, 1) : ivec2(0, -1);
    nearestDepth = min(nearestDepth, texelFetch(u_depth, clamp(centre + step, ivec2(0), g_lastTexel), 0).r);
  }
  vec3 current = toYCoCg(sum / max(weights, 1e-6));
  vec3 mean = m1 / 9.0;
  vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));

  // The nearest surface, as this frame saw it (its jittered view) and as the last frame did.
  vec2 ndc = (at + u_jitter) / vec2(sceneSize) * 2.0 - 1.0;
  vec3 position = unproject(ndc, nearestDepth);
  bool sky = nearestDepth >= 1.0;
  float distanceNow = sky ? kSkyDistance : length(position);
  vec4 clip = u_reprojection * (sky ? vec4(position, 0.0) : vec4(position + u_cameraMotion, 1.0));
  vec2 lastUv = clip.xy / max(clip.w, 1e-6) * 0.5 + 0.5;
  float expected = sky ? kSkyDistance : length(position + u_cameraMotion);

  vec3 resolved = current;
  if (u_historyValid && clip.w > 1e-6 && all(greaterThanEqual(lastUv, vec2(0.0))) &&
      all(lessThanEqual(lastUv, vec2(1.0)))) {
    // Its colour filtered; the distance it saw at the nearest texel (a filtered one mixes surfaces).
    vec4 last = vec4(historyColour(lastUv * vec2(textureSize(u_history, 0))),
                     texelFetch(u_history, ivec2(lastUv * vec2(textureSize(u_history, 0))), 0).a);
    if (abs(last.a - expected) <= kDistanceTolerance * expected) {
      // A moving view trusts the history less: each reprojection resamples (blurs) it, and what moved
      // past an edge should not linger inside the box. Motion in target pixels.
      vec2 motion = lastUv * vec2(textureSize(u_history, 0)) - gl_FragCoord.xy;
      float moving = min(length(motion) / kFastMotion, 1.0);
      vec3 box = mix(kClipSigma, kClipSigmaMoving, moving) * sigma;
      vec3 kept = clipToBox(toYCoCg(compress(max(last.rgb, vec3(0.0)))), mean, box);
      // How near this frame's nearest sample came to the pixel, in target pixels.
      vec2 nearest = offset / u_sceneScale;
      float blend = max(kBlend * exp(-2.0 * dot(nearest, nearest)), kMinBlend);
      blend = mix(blend, kBlendMoving, moving);
      if (u_reactive) blend = max(blend, kBlendReactive * texelFetch(u_reactiveMask, clamp(centre, ivec2(0), g_lastTexel), 0).r);
      resolved = mix(kept, current, blend);
    }
  }
  o_color = vec4(expand(max(fromYCoCg(resolved), vec3(0.0))), distanceNow);
}
