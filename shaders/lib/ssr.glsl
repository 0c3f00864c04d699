// Screen-space reflection: a reflected ray marched against the opaque scene's depth (steps growing
// with the distance, then a binary refinement), and what it sees: the lit scene where it hits, else
// the sky in its direction dimmed by the surface's sky light, so a cave never mirrors a bright sky.
// Shared by the reflection pass (opaque surfaces) and the translucent pass (water, glass). Needs
// lib/lighting.glsl (levelBrightness) and lib/sky.glsl (skyColor) before it.

#include "lib/unproject.glsl"
#include "lib/view_depth.glsl"

layout(binding = UNIT_SSR_DEPTH) uniform sampler2D u_ssrDepth;        // the opaque scene's depth
layout(binding = UNIT_REFLECTION_SCENE) uniform sampler2D u_ssrScene;  // the lit opaque scene

uniform mat4 u_viewProjection;  // camera-relative
uniform int u_maxSteps;
uniform float u_thickness;      // blocks a hit may lie behind the depth buffer's surface
uniform float u_maxDistance;    // blocks

bool offScreen(vec2 uv) { return any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))); }

// Where `p` lands on screen; false behind the camera.
bool screenOf(vec3 p, out vec2 uv) {
  vec4 clip = u_viewProjection * vec4(p, 1.0);
  uv = clip.xy / max(clip.w, 1e-4) * 0.5 + 0.5;
  return clip.w > 1e-4;
}

// A ray in clip space: the projection is linear in homogeneous coordinates, so each step is one
// multiply-add, and the ray's depth along the view (clip w) comes with it.
struct ClipRay {
  vec4 origin, dir;
};

// How far the ray's point at `t` lies behind the depth buffer's surface at its pixel (negative: in
// front). 0: off screen or behind the camera; 1: over sky (nothing to hit there); 2: measured.
int behindAt(ClipRay ray, float t, vec2 size, out float behind, out vec2 uv) {
  behind = 0.0;
  vec4 clip = ray.origin + ray.dir * t;
  if (clip.w <= 1e-4) return 0;
  uv = clip.xy / clip.w * 0.5 + 0.5;
  if (offScreen(uv)) return 0;
  float depth = texelFetch(u_ssrDepth, ivec2(uv * size), 0).r;
  if (depth >= 1.0) return 1;
  behind = clip.w - viewDepth(depth);
  return 2;
}

// How far the ray goes before it leaves the screen (the frustum's side planes, -w <= x, y <= w, and
// the near side), or `end`: beyond, nothing it meets is in the image.
float onScreenLength(ClipRay ray, float end) {
  vec4 start = vec4(ray.origin.w - ray.origin.xy, ray.origin.w + ray.origin.xy);  // >= 0 on screen
  vec4 slope = vec4(ray.dir.w - ray.dir.xy, ray.dir.w + ray.dir.xy);
  for (int k = 0; k < 4; ++k) {
    if (slope[k] < 0.0) end = min(end, max(start[k], 0.0) / -slope[k]);
  }
  if (ray.dir.w < 0.0) end = min(end, max(ray.origin.w - 1e-3, 0.0) / -ray.dir.w);
  return end;
}

bool march(vec3 origin, vec3 dir, out vec2 hitUv) {
  ClipRay ray = ClipRay(u_viewProjection * vec4(origin, 1.0), u_viewProjection * vec4(dir, 0.0));
  vec2 size = vec2(textureSize(u_ssrDepth, 0));
  // Whatever lies past the fog's end shows the sky's colour (lib/sky.glsl): the ray goes no further
  // than where its horizontal distance from the camera must have passed it, in as many steps as keep
  // their spacing.
  float reach = min(u_maxDistance, (u_fogRange.y + length(origin.xz)) / max(length(dir.xz), 1e-3));
  int steps = max(int(ceil(float(u_maxSteps) * sqrt(reach / u_maxDistance))), 1);
  // A step that would leave the screen stops a hair inside its edge instead, and is the last: a
  // crossing just before the ray leaves is still found.
  float end = onScreenLength(ray, reach) * 0.999;
  float near = 0.0;  // the last point seen in front of the depth buffer
  bool inFront = true;
  for (int i = 1; i <= steps; ++i) {
    float f = float(i) / float(steps);
    float t = min(reach * f * f, end);  // fine steps near the surface, where most hits are
    float behind;
    vec2 uv;
    int seen = behindAt(ray, t, size, behind, uv);
    if (seen == 0) return false;  // the ray left the screen: what it would hit is not in the image
    bool nowBehind = seen == 2 && behind > 0.0;
    if (nowBehind && inFront) {
      // It went behind a surface since the last step: find where (a binary refinement between the
      // two), and take it if it lies within the thickness there. A coarse step that overshoots a
      // thin block still finds it; a ray passing behind one goes on.
      float far = t;
      for (int k = 0; k < 6; ++k) {
        float mid = 0.5 * (near + far);
        if (behindAt(ray, mid, size, behind, uv) == 2 && behind > 0.0) far = mid; else near = mid;
      }
      if (behindAt(ray, far, size, behind, uv) == 2 && behind < u_thickness + far * 0.02) {
        return screenOf(origin + dir * far, hitUv) && !offScreen(hitUv);
      }
    }
    inFront = !nowBehind;
    if (inFront) near = t;
    if (t >= end) return false;
  }
  return false;
}

// Screen edges hold no more of the reflected world: hits near them fade to the sky fallback.
float edgeFade(vec2 uv) {
  vec2 d = min(uv, 1.0 - uv);
  return smoothstep(0.0, 0.05, min(d.x, d.y));
}

// The sky a ray from `from` (camera-relative) in `dir` reflects where it hits nothing, with the clouds
// it passes, dimmed by the surface's sky light.
vec3 reflectedSky(vec3 from, vec3 dir, float skyLight) {
  return skyAlong(from, dir) * levelBrightness(skyLight);
}

// What a ray reflects: the hit's lit colour, else `missed` (the reflected sky, or under water the
// water's colour).
vec3 reflectedLight(vec3 missed, bool hit, vec2 hitUv) {
  return hit ? mix(missed, texture(u_ssrScene, hitUv).rgb, edgeFade(hitUv)) : missed;
}
