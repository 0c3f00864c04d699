// Minecraft's cloud layer (core/cloud_layer.h): the map's texels 12 blocks wide, flat on a plane or
// fancy 4-block boxes, in front of whatever lies beyond them, and their shadows on the ground.
// Included by lib/sky.glsl; without CLOUDS every function is the clear sky's, so callers need no #ifdef.
// Layer space: x and z wrapped into the map (blocks, drift applied), y above the layer's bottom.

layout(binding = UNIT_CLOUDS) uniform sampler2D u_clouds;
uniform vec3 u_cloudOrigin;   // the camera in layer space
uniform vec3 u_cloudLight;    // the shadow-casting light's radiance (faded at the horizon)
uniform vec3 u_cloudToLight;  // unit, towards it

#ifdef CLOUDS
const int kCloudMaxSteps = int(CLOUD_RANGE / CLOUD_CELL) * 2 + 2;  // cells a ray crosses within range

// A cell's cover (0..1), the map repeating.
float cloudCover(ivec2 cell) {
  ivec2 size = textureSize(u_clouds, 0);
  ivec2 wrapped = cell - size * ivec2(floor(vec2(cell) / vec2(size)));  // % is undefined below 0
  return texelFetch(u_clouds, wrapped, 0).r;
}

bool cloudCell(ivec2 cell) { return cloudCover(cell) >= 0.5; }

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
#endif

// The clouds a ray from `from` (camera-relative) along unit `dir` passes before `maxT` blocks:
// premultiplied colour and coverage (0 where it meets none).
vec4 cloudsAlong(vec3 from, vec3 dir, float maxT) {
#ifdef CLOUDS
  vec3 o = u_cloudOrigin + from;
  float horizontal = length(dir.xz);
  if (horizontal > 1e-6) maxT = min(maxT, CLOUD_RANGE / horizontal);
#ifdef CLOUDS_FANCY
  // The slab the boxes fill, then the cells along the ray (a 2D walk: each cell is the slab's height).
  float t0 = 0.0, t1 = maxT;
  if (abs(dir.y) > 1e-6) {
    float ta = -o.y / dir.y, tb = (CLOUD_THICKNESS - o.y) / dir.y;
    t0 = max(min(ta, tb), 0.0);
    t1 = min(max(ta, tb), maxT);
  } else if (o.y < 0.0 || o.y > CLOUD_THICKNESS) {
    return vec4(0.0);
  }
  if (t0 >= t1) return vec4(0.0);
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
  float below = 0.5 * CLOUD_THICKNESS - p.y;
  if (below <= 0.0 || u_cloudToLight.y <= 0.0) return 1.0;
  // Bilinear from whole-texel fetches (a filtered lookup costs far more on llvmpipe), texel centres
  // at the cells' centres.
  vec2 at = (p.xz + u_cloudToLight.xz * (below / max(u_cloudToLight.y, 0.05))) / CLOUD_CELL - 0.5;
  ivec2 i = ivec2(floor(at));
  vec2 f = at - vec2(i);
  float cover = mix(mix(cloudCover(i), cloudCover(i + ivec2(1, 0)), f.x),
                    mix(cloudCover(i + ivec2(0, 1)), cloudCover(i + ivec2(1, 1)), f.x), f.y);
  cover = smoothstep(0.3, 0.7, cover);
  return 1.0 - CLOUD_SHADOW * cover * smoothstep(0.0, 0.1, u_cloudToLight.y);
#else
  return 1.0;
#endif
}
