#include "scene_render/shadow_truth.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "core/octahedral.h"
#include "render/shadow_map.h"
#include "world/voxel_ray.h"

namespace terrasol {
namespace {

enum class Ray { Lit, Shadowed, Ambiguous };

// How much a pixel's shadow term must change, across 0.5, to count as flicker.
constexpr float kFlipMargin = 0.01f;

// The first block along unit `dir` from `origin` decides: an opaque cube shadows, anything else drawn
// (cutout, translucent) is ambiguous. A model block (World::shapes) counts only where the ray meets
// its boxes: opaque, it shadows there.
Ray march(const World& world, glm::dvec3 origin, glm::dvec3 dir, double maxDistance) {
  const BlockRegistry& blocks = world.blocks();
  const BlockShapes* shapes = world.shapes();
  Ray ray = Ray::Lit;
  walkVoxels(origin, dir, maxDistance, [&](const VoxelStep& s) {
    if (s.cell.y >= kMaxY) return true;  // out of the top of the world: open sky
    if (s.cell.y < kMinY) return ray = Ray::Shadowed, true;
    const BlockPos pos{s.cell.x, s.cell.y, s.cell.z};
    if (!world.isLoaded(ChunkPos::of(pos))) return true;  // nothing there to cast, in the map either
    const BlockId id = world.getBlock(pos);
    if (id == kAir) return false;
    if (shapes && blocks[id].shape == BlockShape::Model) {
      if (!firstBoxHit(shapes->boxes(id), s.cell, origin, dir)) return false;
      ray = blocks[id].layer == RenderLayer::Opaque ? Ray::Shadowed : Ray::Ambiguous;
      return true;
    }
    ray = blocks[id].isOpaqueCube() ? Ray::Shadowed : Ray::Ambiguous;
    return true;
  });
  return ray;
}

// The ray from the point and from four points 0.05 blocks beside it: if they disagree, the ray grazes
// an edge and the answer depends on sub-texel detail no shadow map has.
Ray truthAt(const World& world, glm::dvec3 point, glm::dvec3 normal, glm::dvec3 toLight, double maxDistance) {
  const glm::dvec3 origin = point + normal * 0.02;
  const Ray centre = march(world, origin, toLight, maxDistance);
  if (centre == Ray::Ambiguous) return centre;
  glm::dvec3 t1 = glm::cross(normal, std::abs(normal.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
  t1 = glm::normalize(t1);
  const glm::dvec3 t2 = glm::cross(normal, t1);
  for (const glm::dvec3 d : {t1, -t1, t2, -t2}) {
    if (march(world, origin + d * 0.05, toLight, maxDistance) != centre) return Ray::Ambiguous;
  }
  return centre;
}

// A pixel as a world point and its vertex normal; false for sky.
struct Surface {
  glm::dvec3 relative;  // camera-relative
  glm::dvec3 normal;
};
bool surfaceAt(const GBufferPixels& f, const FrameGeometry& g, int x, int y, Surface& s) {
  const std::size_t i =
      static_cast<std::size_t>(y) * static_cast<std::size_t>(f.size.x) + static_cast<std::size_t>(x);
  const float depth = f.depth[i];
  if (!(depth < 1.0f)) return false;
  const glm::vec4 ndc((x + 0.5f) / f.size.x * 2.0f - 1.0f, (y + 0.5f) / f.size.y * 2.0f - 1.0f,
                      depth * 2.0f - 1.0f, 1.0f);
  const glm::vec4 p = g.inverseViewProjection * ndc;
  s.relative = glm::dvec3(p) / static_cast<double>(p.w);
  s.normal = octDecode(glm::dvec2(f.normals[i].z, f.normals[i].w));
  return true;
}

bool facesLight(const Surface& s, const FrameGeometry& g) {
  return glm::dot(s.normal, glm::dvec3(g.toLight)) > 0.05;
}

int bucketOf(double distance) {
  return distance < 8.0 ? 0 : distance < 32.0 ? 1 : distance < 64.0 ? 2 : 3;
}

}  // namespace

ShadowError measureShadowError(const World& world, const GBufferPixels& frame, const FrameGeometry& geometry,
                               float distance) {
  ShadowError e;
  const glm::dvec3 toLight = glm::normalize(glm::dvec3(geometry.toLight));
  for (int y = 0; y < frame.size.y; ++y)
    for (int x = 0; x < frame.size.x; ++x) {
      Surface s;
      if (!surfaceAt(frame, geometry, x, y, s) || !facesLight(s, geometry)) continue;
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.size.x) + static_cast<std::size_t>(x);
      const float rendered = frame.scene[i].a;
      if (frame.light[i].g == 0 && rendered > 0.0f && geometry.shadowMapShown) ++e.caveLeakPixels;
      const double d = glm::length(s.relative);
      if (d > distance) continue;
      ShadowCounts& bucket = e.byDistance[static_cast<std::size_t>(bucketOf(d))];
      const Ray truth = truthAt(world, geometry.camera + s.relative, s.normal, toLight,
                                distance + static_cast<double>(kShadowCasterReach));
      for (ShadowCounts* c : {&e.total, &bucket}) {
        if (truth == Ray::Ambiguous) {
          ++c->ambiguous;
          continue;
        }
        ++c->evaluated;
        if (truth == Ray::Lit && rendered < 0.5f) ++c->falseShadow;
        if (truth == Ray::Shadowed && rendered >= 0.5f) ++c->falseLit;
      }
    }
  return e;
}

double flickerPercent(const GBufferPixels& a, const GBufferPixels& b, const FrameGeometry& geometry,
                      float distance, std::size_t& compared) {
  compared = 0;
  std::size_t flips = 0;
  for (int y = 0; y < a.size.y; ++y)
    for (int x = 0; x < a.size.x; ++x) {
      Surface s;
      // The map's outer tenth is left out: a point there moves in and out of the map as it steps.
      if (!surfaceAt(a, geometry, x, y, s) || !facesLight(s, geometry) ||
          glm::length(s.relative) > 0.9 * distance) {
        continue;
      }
      const auto i = static_cast<std::size_t>(y * a.size.x + x);
      ++compared;
      // A flip crosses 0.5 by a visible amount: llvmpipe's 8-bit filter weights move a term sitting on
      // 0.5 (8 of 16 taps lit) by ~1e-4 when the map's float offsets round differently.
      const float ta = a.scene[i].a, tb = b.scene[i].a;
      flips += (ta >= 0.5f) != (tb >= 0.5f) && std::abs(ta - tb) > kFlipMargin;
    }
  return compared ? 100.0 * static_cast<double>(flips) / static_cast<double>(compared) : 0.0;
}

nlohmann::json shadowErrorJson(const ShadowError& error, double flickerPct, std::size_t flickerPoints) {
  auto split = [](const ShadowCounts& c) {
    const double all = static_cast<double>(c.evaluated + c.ambiguous);
    auto pct = [](std::size_t n, double of) { return of > 0.0 ? 100.0 * static_cast<double>(n) / of : 0.0; };
    return nlohmann::json{{"evaluated_pixels", c.evaluated},
                          {"false_shadow_pct", pct(c.falseShadow, static_cast<double>(c.evaluated))},
                          {"false_lit_pct", pct(c.falseLit, static_cast<double>(c.evaluated))},
                          {"ambiguous_pct", pct(c.ambiguous, all)}};
  };
  nlohmann::json out = split(error.total);
  out["cave_leak_pixels"] = error.caveLeakPixels;
  const char* names[4] = {"0-8", "8-32", "32-64", "64+"};
  for (std::size_t b = 0; b < 4; ++b) out["by_distance"][names[b]] = split(error.byDistance[b]);
  out["flicker_pct"] = flickerPct;
  out["flicker_points"] = flickerPoints;
  return out;
}

}  // namespace terrasol
