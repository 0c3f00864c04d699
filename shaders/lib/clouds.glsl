// Minecraft's cloud layer (core/cloud_layer.h): the map's texels 12 blocks wide, flat on a plane,
// fancy 4-block boxes or a volumetric slab, in front of whatever lies beyond them, and their shadows
// on the ground.
// Included by lib/sky.glsl; without CLOUDS every function is the clear sky's, so callers need no #ifdef.
// Layer space: x and z wrapped into the map (blocks, drift applied), y above the layer's bottom.

layout(binding = UNIT_CLOUDS) uniform sampler2D u_clouds;
uniform vec3 u_cloudOrigin;   // the camera in layer space
uniform vec3 u_cloudLight;    // the shadow-casting light's radiance (faded at the horizon)
uniform vec3 u_cloudToLight;  // unit, towards it
uniform vec2 u_cloudNoise;    // pixels the volumetric march's start pattern moves this frame

#ifdef CLOUDS
const int kCloudMaxSteps = int(CLOUD_RANGE / CLOUD_CELL) * 2 + 2;  // cells a ray crosses within range

// A cell's cover (0..1), the map repeating.
float cloudCover(ivec2 cell) {
  ivec2 size = textureSize(u_clouds, 0);
  ivec2 wrapped = cell - size * ivec2(floor(vec2(cell) / vec2(size)));  // % is undefined below 0
  return texelFetch(u_clouds, wrapped, 0).r;
}

bool cloudCell(ivec2 cell) { return cloudCover(cell) >= 0.5; }

// The map's cover at a layer-space point, bilinear from whole-texel fetches (a filtered lookup costs
// far more on llvmpipe), texel centres at the cells' centres.
float filteredCloudCover(vec2 xz) {
  vec2 at = xz / CLOUD_CELL - 0.5;
  ivec2 i = ivec2(floor(at));
  vec2 f = at - vec2(i);
  return mix(mix(cloudCover(i), cloudCover(i + ivec2(1, 0)), f.x),
             mix(cloudCover(i + ivec2(0, 1)), cloudCover(i + ivec2(1, 1)), f.x), f.y);
}

// The slab the layer fills, from its bottom.
#ifdef CLOUDS_VOLUMETRIC
const float kCloudSlab = CLOUD_VOLUME_THICKNESS;
#else
const float kCloudSlab = CLOUD_THICKNESS;
#endif

// The span [t0, t1] of a ray from layer-space `o` along `dir` inside the slab, before `maxT`; false
// where it misses.
bool cloudSlabSpan(vec3 o, vec3 dir, float maxT, out float t0, out float t1) {
  t0 = 0.0;
  t1 = maxT;
  if (abs(dir.y) > 1e-6) {
    float ta = -o.y / dir.y, tb = (kCloudSlab - o.y) / dir.y;
    t0 = max(min(ta, tb), 0.0);
    t1 = min(max(ta, tb), maxT);
  } else if (o.y < 0.0 || o.y > kCloudSlab) {
    return false;
  }
  return t0 < t1;
}

// A face of the layer facing `normal`, lit by the light wrapped round (light scatters into a cloud)
// and by the sky's mean radiance, faded into the sky along `dir` with `distance` (horizontal blocks).
vec4 cloudFace(vec3 normal, vec3 dir, float distance) {
  vec3 sky = SKY_RADIANCE * 0.5 * (u_skyZenith + u_skyHorizon);
  float wrapped = 0.4 + 0.6 * max(dot(normal, u_cloudToLight), 0.0);
  vec3 color = CLOUD_ALBEDO * (u_cloudLight * wrapped + sky);
  float far = distance / CLOUD_RANGE;
  color = mix(color, skyColor(dir), 0.6 * far * far);
  float alpha = CLOUD_ALPHA * (1.0 - smoothstep(0.6, 1.0, far));
  return vec4(color * alpha, alpha);
}

#ifdef CLOUDS_VOLUMETRIC
// Value noise from hashed lattice corners, smoothly interpolated (0..1): the map gives the clouds'
// places, this their billows. A hash, not a texture: the same at every tick for the same point.
float cloudHash(vec3 p) {
  p = fract(p * 0.1031);
  p += dot(p, p.zyx + 31.32);
  return fract((p.x + p.y) * p.z);
}
float cloudNoise(vec3 p) {
  vec3 i = floor(p), f = p - i;
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(cloudHash(i), cloudHash(i + vec3(1, 0, 0)), f.x),
                 mix(cloudHash(i + vec3(0, 1, 0)), cloudHash(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(cloudHash(i + vec3(0, 0, 1)), cloudHash(i + vec3(1, 0, 1)), f.x),
                 mix(cloudHash(i + vec3(0, 1, 1)), cloudHash(i + vec3(1, 1, 1)), f.x), f.y),
             f.z);
}

// Density (0..1) at a layer-space point: the map's cover, rising higher in the slab where it is
// thicker (flat bottoms, rounded tops), eaten at its edges by two octaves of noise.
float cloudDensity(vec3 p) {
  float h = p.y / kCloudSlab;
  if (h <= 0.0 || h >= 1.0) return 0.0;
  float cover = filteredCloudCover(p.xz);
  if (cover <= 0.05) return 0.0;
  float top = 0.25 + 0.75 * cover;
  float profile = smoothstep(0.0, 0.1, h) * (1.0 - smoothstep(0.6 * top, top, h));
  float billows = 0.65 * cloudNoise(p / 12.0) + 0.35 * cloudNoise(p / 5.0);
  return clamp((cover * profile - 0.55 * (1.0 - billows)) * 2.5, 0.0, 1.0);
}

// Henyey-Greenstein's phase function times 4 pi (1 where scattering is even).
float cloudPhase(float cosTheta, float g) {
  float g2 = g * g;
  return (1.0 - g2) / pow(max(1.0 + g2 - 2.0 * g * cosTheta, 1e-4), 1.5);
}

// The light a point's cloud scatters towards the camera (per unit of density): the light through the
// cloud above it towards the light (Beer-Lambert over a few steps), forward-scattered with a silver
// lining, and the sky's mean radiance, more of it near the top.
vec3 cloudInScatter(vec3 p, vec3 dir) {
  float depth = 0.0;
  for (int k = 1; k <= CLOUD_LIGHT_STEPS; ++k) depth += cloudDensity(p + u_cloudToLight * (2.5 * float(k)));
  float toLight = exp(-CLOUD_EXTINCTION * 2.5 * depth);
  float cosTheta = dot(dir, u_cloudToLight);
  float phase = mix(cloudPhase(cosTheta, 0.6), cloudPhase(cosTheta, -0.25), 0.35);
  vec3 sky = SKY_RADIANCE * 0.5 * (u_skyZenith + u_skyHorizon);
  return CLOUD_ALBEDO * (u_cloudLight * toLight * phase + sky * (0.5 + 0.5 * p.y / kCloudSlab));
}

// The ray's part in the slab, [t0, t1], marched in CLOUD_VOLUME_STEPS steps from a per-pixel offset
// (the banding becomes a fine noise): premultiplied colour and coverage, energy-conserving (each step
// scatters what it takes out of the light behind it), faded into the sky towards the layer's range.
vec4 cloudVolume(vec3 o, vec3 dir, float t0, float t1, float horizontal) {
  // Along the slab (inside it, or at the horizon) the span runs to hundreds of blocks: steps that
  // long turn the offset into a visible pattern, and the nearer clouds hide the rest anyway.
  t1 = min(t1, t0 + CLOUD_VOLUME_SPAN);
  float dt = (t1 - t0) / float(CLOUD_VOLUME_STEPS);
  vec2 pixel = gl_FragCoord.xy + u_cloudNoise;  // interleaved gradient noise
  float offset = fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
  float transmittance = 1.0;
  vec3 color = vec3(0.0);
  for (int i = 0; i < CLOUD_VOLUME_STEPS; ++i) {
    vec3 p = o + dir * (t0 + (float(i) + offset) * dt);
    float density = cloudDensity(p);
    if (density <= 0.0) continue;
    float through = exp(-CLOUD_EXTINCTION * density * dt);
    color += transmittance * (1.0 - through) * cloudInScatter(p, dir);
    transmittance *= through;
    if (transmittance < 0.02) break;
  }
  float far = 0.5 * (t0 + t1) * horizontal / CLOUD_RANGE;
  float fade = 1.0 - smoothstep(0.6, 1.0, far);
  float alpha = (1.0 - transmittance) * fade;
  color = mix(color, skyColor(dir) * (1.0 - transmittance), 0.6 * far * far) * fade;
  return vec4(color, alpha);
}
#endif
#endif

// The clouds a ray from `from` (camera-relative) along unit `dir` passes before `maxT` blocks:
// premultiplied colour and coverage (0 where it meets none).
vec4 cloudsAlong(vec3 from, vec3 dir, float maxT) {
#ifdef CLOUDS
  vec3 o = u_cloudOrigin + from;
  float horizontal = length(dir.xz);
  if (horizontal > 1e-6) maxT = min(maxT, CLOUD_RANGE / horizontal);
#if defined(CLOUDS_VOLUMETRIC)
  float t0, t1;
  if (!cloudSlabSpan(o, dir, maxT, t0, t1)) return vec4(0.0);
  return cloudVolume(o, dir, t0, t1, horizontal);
#elif defined(CLOUDS_FANCY)
  // The slab the boxes fill, then the cells along the ray (a 2D walk: each cell is the slab's height).
  float t0, t1;
  if (!cloudSlabSpan(o, dir, maxT, t0, t1)) return vec4(0.0);
  vec3 p = o + dir * t0;
  ivec2 cell = ivec2(floor(p.xz / CLOUD_CELL));
  ivec2 stride = ivec2(sign(dir.xz));
  vec2 invDir = 1.0 / max(abs(dir.xz), vec2(1e-6));
  // Ray distance to the next cell boundary on x and z, and between boundaries.
  vec2 boundary = (vec2(cell) + max(vec2(stride), 0.0)) * CLOUD_CELL;
  vec2 next = t0 + abs(boundary - p.xz) * invDir;
  vec2 across = CLOUD_CELL * invDir;
  vec3 normal = t0 > 0.0 ? vec3(0.0, -sign(dir.y), 0.0) : -dir;  // inside the slab: facing the camera
  float t = t0;
  for (int i = 0; i < kCloudMaxSteps; ++i) {
    if (cloudCell(cell)) return cloudFace(normal, dir, t * horizontal);
    if (next.x < next.y) {
      t = next.x;
      next.x += across.x;
      cell.x += stride.x;
      normal = vec3(-float(stride.x), 0.0, 0.0);
    } else {
      t = next.y;
      next.y += across.y;
      cell.y += stride.y;
      normal = vec3(0.0, 0.0, -float(stride.y));
    }
    if (t >= t1) break;
  }
  return vec4(0.0);
#else
  // Flat: the plane at the layer's bottom, one texel where the ray meets it.
  if (dir.y * o.y >= 0.0) return vec4(0.0);  // moving away from the plane, or along it
  float t = -o.y / dir.y;
  if (t > maxT) return vec4(0.0);
  vec2 p = o.xz + dir.xz * t;
  if (!cloudCell(ivec2(floor(p / CLOUD_CELL)))) return vec4(0.0);
  return cloudFace(vec3(0.0, -sign(dir.y), 0.0), dir, t * horizontal);
#endif
#else
  return vec4(0.0);
#endif
}

// `color`, seen from `from` along `dir` at `distance` blocks, behind the clouds in between.
vec3 behindClouds(vec3 color, vec3 from, vec3 dir, float distance) {
  vec4 clouds = cloudsAlong(from, dir, distance);
  return color * (1.0 - clouds.a) + clouds.rgb;
}

// The sky a ray from `from` along `dir` sees, with the clouds it passes.
vec3 skyAlong(vec3 from, vec3 dir) { return behindClouds(skyColor(dir), from, dir, 1e9); }

// The share of the direct light that reaches `position` (camera-relative) past the layer above it:
// the map read filtered where the light's ray crosses the layer's middle, its edges tightened to about
// a third of a cell, so shadows are soft but keep the clouds' shapes.
float cloudShadow(vec3 position) {
#if defined(CLOUDS) && defined(CLOUD_SHADOWS)
  vec3 p = u_cloudOrigin + position;
  float below = 0.5 * kCloudSlab - p.y;
  if (below <= 0.0 || u_cloudToLight.y <= 0.0) return 1.0;
  float cover = filteredCloudCover(p.xz + u_cloudToLight.xz * (below / max(u_cloudToLight.y, 0.05)));
  cover = smoothstep(0.3, 0.7, cover);
  return 1.0 - CLOUD_SHADOW * cover * smoothstep(0.0, 0.1, u_cloudToLight.y);
#else
  return 1.0;
#endif
}
