#include "scene_render/reflection_truth.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <optional>

#include "core/octahedral.h"
#include "world/voxel_ray.h"

namespace terrasol {
namespace {

struct Truth {
  enum class Kind { Nothing, Block, Ambiguous } kind = Kind::Nothing;
  glm::ivec3 block{0};
  glm::dvec3 point{0.0};  // where the ray enters the block (world)
};

// The first block along the ray that the depth buffer would hold: an opaque cube is a hit; a cutout
// or partial block is ambiguous (its depth is there only where its texels are); translucent blocks
// are not in the depth buffer, so the ray goes on through them. A model block (World::shapes) is met
// only where the ray meets its boxes: opaque, it is a hit there.
Truth trace(const World& world, glm::dvec3 origin, glm::dvec3 dir, double maxDistance) {
  const BlockRegistry& blocks = world.blocks();
  const BlockShapes* shapes = world.shapes();
  Truth truth;
  walkVoxels(origin, dir, maxDistance, [&](const VoxelStep& s) {
    if (s.cell.y >= kMaxY || s.cell.y < kMinY) return true;  // out of the world: nothing
    const BlockPos pos{s.cell.x, s.cell.y, s.cell.z};
    if (!world.isLoaded(ChunkPos::of(pos))) return true;
    const BlockId id = world.getBlock(pos);
    const BlockType& type = blocks[id];
    if (type.layer == RenderLayer::None || type.layer == RenderLayer::Translucent) return false;
    double t = s.t;
    if (shapes && type.shape == BlockShape::Model) {
      const auto hit = firstBoxHit(shapes->boxes(id), s.cell, origin, dir);
      if (!hit) return false;
      t = hit->t;
      truth.kind = type.layer == RenderLayer::Opaque ? Truth::Kind::Block : Truth::Kind::Ambiguous;
    } else {
      truth.kind = type.isOpaqueCube() ? Truth::Kind::Block : Truth::Kind::Ambiguous;
    }
    truth.block = s.cell;
    truth.point = origin + dir * t;
    return true;
  });
  return truth;
}

glm::dvec3 unproject(const FrameGeometry& g, glm::dvec2 ndc, double depth) {
  const glm::vec4 p =
      g.inverseViewProjection * glm::vec4(glm::vec2(ndc), static_cast<float>(depth * 2.0 - 1.0), 1.0f);
  return glm::dvec3(p) / static_cast<double>(p.w);
}

std::size_t indexOf(glm::ivec2 pixel, glm::ivec2 size) {
  return static_cast<std::size_t>(pixel.y) * static_cast<std::size_t>(size.x) +
         static_cast<std::size_t>(pixel.x);
}

glm::ivec2 pixelAt(glm::dvec2 uv, glm::ivec2 size) {
  return glm::clamp(glm::ivec2(glm::floor(uv * glm::dvec2(size))), glm::ivec2(0), size - 1);
}

glm::dvec3 vertexNormalAt(const GBufferPixels& f, std::size_t i, bool surfaceNormals) {
  const glm::vec4 n = f.normals[i];
  return octDecode(surfaceNormals ? glm::dvec2(n.z, n.w) : glm::dvec2(n.x, n.y));
}

// The block the G-buffer shows at `uv` (world), or nothing over sky.
std::optional<glm::ivec3> blockAt(const GBufferPixels& f, const FrameGeometry& g, glm::dvec2 uv,
                                  bool surfaceNormals) {
  const glm::ivec2 p = pixelAt(uv, f.size);
  const std::size_t i = indexOf(p, f.size);
  if (f.depth[i] >= 1.0f) return std::nullopt;
  const glm::dvec2 ndc = (glm::dvec2(p) + 0.5) / glm::dvec2(f.size) * 2.0 - 1.0;
  const glm::dvec3 point =
      g.camera + unproject(g, ndc, f.depth[i]) - vertexNormalAt(f, i, surfaceNormals) * 0.01;
  return glm::ivec3(glm::floor(point));
}

// Where the truth's hit point lies on screen; nothing behind the camera.
std::optional<glm::dvec2> screenOf(const FrameGeometry& g, const Truth& truth) {
  const glm::vec4 clip = g.viewProjection * glm::vec4(glm::vec3(truth.point - g.camera), 1.0f);
  if (clip.w <= 1e-4f) return std::nullopt;
  return glm::dvec2(clip.x, clip.y) / static_cast<double>(clip.w) * 0.5 + 0.5;
}

// Whether the truth's hit point is what the screen shows there.
bool visibleOnScreen(const GBufferPixels& f, const FrameGeometry& g, const Truth& truth,
                     bool surfaceNormals) {
  const std::optional<glm::dvec2> uv = screenOf(g, truth);
  if (!uv || uv->x < 0.0 || uv->y < 0.0 || uv->x >= 1.0 || uv->y >= 1.0) return false;
  const auto shown = blockAt(f, g, *uv, surfaceNormals);
  return shown && *shown == truth.block;
}

int bucketOf(double distance) {
  return distance < 8.0 ? 0 : distance < 32.0 ? 1 : distance < 64.0 ? 2 : 3;
}

// What the march found against the truth: its block, and whether it lies within a G-buffer pixel of
// the truth's point on screen.
struct Marched {
  std::optional<glm::ivec3> block;
  bool besideTruth = false;
};

void count(ReflectionCounts& c, const Truth& truth, const Marched& marched, bool visible) {
  if (truth.kind == Truth::Kind::Ambiguous) {
    ++c.ambiguous;
    return;
  }
  ++c.evaluated;
  const bool truthHit = truth.kind == Truth::Kind::Block;
  if (truthHit && marched.block) {
    ++(*marched.block == truth.block ? c.agree : marched.besideTruth ? c.borderHit : c.wrongHit);
  } else if (!truthHit && !marched.block) {
    ++c.agree;
  } else if (!truthHit) {
    ++c.falseHit;
  } else {
    ++(visible ? c.missedOnScreen : c.missedOffScreen);
  }
}

// One marched ray: `position` (camera-relative) and the normals it left from, what the pass wrote.
struct MarchedRay {
  glm::dvec3 position, normal, vertexNormal;
  glm::vec4 hit, reflected;  // ReflectionPixels::hits and what was added or reflected
  float skyLight = 0.0f;     // 0..1
};

void evaluate(ReflectionError& e, ReflectionCounts& part, const World& world, const GBufferPixels& f,
              const FrameGeometry& g, const MarchedRay& ray, float maxDistance, bool surfaceNormals) {
  const glm::dvec3 toViewer = -ray.position / std::max(glm::length(ray.position), 1e-6);
  glm::dvec3 dir = glm::reflect(-toViewer, ray.normal);
  dir = glm::normalize(dir - ray.vertexNormal * std::min(glm::dot(dir, ray.vertexNormal) - 0.01, 0.0));
  const Truth truth = trace(world, g.camera + ray.position + ray.vertexNormal * 0.02, dir, maxDistance);
  Marched marched;
  if (ray.hit.z > 0.5f) {
    const glm::dvec2 hitUv{ray.hit.x, ray.hit.y};
    marched.block = blockAt(f, g, hitUv, surfaceNormals);
    const std::optional<glm::dvec2> truthUv = screenOf(g, truth);
    marched.besideTruth = truthUv && glm::length((*truthUv - hitUv) * glm::dvec2(f.size)) <= 1.0;
  }
  const bool visible =
      truth.kind == Truth::Kind::Block && !marched.block && visibleOnScreen(f, g, truth, surfaceNormals);
  count(e.total, truth, marched, visible);
  count(part, truth, marched, visible);
  count(e.byDistance[static_cast<std::size_t>(bucketOf(glm::length(ray.position)))], truth, marched, visible);
  const glm::vec4 light = ray.reflected;
  if (ray.hit.z < 0.5f && ray.skyLight == 0.0f && std::max({light.r, light.g, light.b}) > 1e-4f)
    ++e.skyLeakPixels;
}

// The face normal nearest a mapped normal: the axis it leans along most.
glm::dvec3 faceNormalOf(glm::dvec3 n) {
  const glm::dvec3 a = glm::abs(n);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
  glm::dvec3 face{0.0};
  face[axis] = n[axis] < 0.0 ? -1.0 : 1.0;
  return face;
}

}  // namespace

ReflectionError measureReflectionError(const World& world, const GBufferPixels& f, const ReflectionPixels& r,
                                       const FrameGeometry& g, float maxDistance, bool surfaceNormals) {
  ReflectionError e;
  for (int y = 0; y < r.size.y; ++y)
    for (int x = 0; x < r.size.x; ++x) {
      const std::size_t ri = indexOf({x, y}, r.size);
      // The target pixel's centre: where the march from water and glass was rasterized, and (scaled)
      // the G-buffer pixel the march from opaque surfaces read.
      const glm::dvec2 uv = (glm::dvec2(x, y) + 0.5) / glm::dvec2(r.size);
      if (const glm::vec4 hit = r.hits[ri]; hit.z >= 0.0f) {
        // The G-buffer pixel the march read: lib/screen_position.glsl's pixelUnder, in the same
        // integer arithmetic (a float product lands on pixel borders at even scales).
        const glm::ivec2 gp = glm::min((2 * glm::ivec2(x, y) + 1) * f.size / (2 * r.size), f.size - 1);
        const std::size_t gi = indexOf(gp, f.size);
        if (f.depth[gi] < 1.0f) {
          const glm::dvec2 ndc = (glm::dvec2(gp) + 0.5) / glm::dvec2(f.size) * 2.0 - 1.0;
          MarchedRay ray{unproject(g, ndc, f.depth[gi]),
                         octDecode(glm::dvec2(f.normals[gi].x, f.normals[gi].y)),
                         vertexNormalAt(f, gi, surfaceNormals),
                         hit,
                         r.added[ri],
                         f.light[gi].g / 255.0f};
          evaluate(e, e.opaque, world, f, g, ray, maxDistance, surfaceNormals);
        }
      }
      if (r.surfaceHits.empty()) continue;
      if (const glm::vec4 hit = r.surfaceHits[ri]; hit.z >= 0.0f) {
        // The surface lies along the pixel's view ray at the depth the march wrote.
        const glm::dvec3 far = unproject(g, uv * 2.0 - 1.0, 1.0);
        const double farDepth = (g.viewProjection * glm::vec4(glm::vec3(far), 1.0f)).w;
        const glm::vec4 n = r.surfaceNormals[ri];
        const glm::dvec3 normal = glm::normalize(glm::dvec3(n));
        MarchedRay ray{far * (static_cast<double>(hit.w) / farDepth),
                       normal,
                       faceNormalOf(normal),
                       hit,
                       r.surfaceReflected[ri],
                       n.w};
        evaluate(e, e.translucent, world, f, g, ray, maxDistance, surfaceNormals);
      }
    }
  return e;
}

nlohmann::json reflectionErrorJson(const ReflectionError& error) {
  auto split = [](const ReflectionCounts& c) {
    const auto pct = [](std::size_t n, std::size_t of) {
      return of > 0 ? 100.0 * static_cast<double>(n) / static_cast<double>(of) : 0.0;
    };
    return nlohmann::json{{"evaluated_pixels", c.evaluated},
                          {"agree_pct", pct(c.agree, c.evaluated)},
                          {"agree_of_reachable_pct", pct(c.agree, c.evaluated - c.missedOffScreen)},
                          {"wrong_hit_pct", pct(c.wrongHit, c.evaluated)},
                          {"border_hit_pct", pct(c.borderHit, c.evaluated)},
                          {"missed_on_screen_pct", pct(c.missedOnScreen, c.evaluated)},
                          {"missed_off_screen_pct", pct(c.missedOffScreen, c.evaluated)},
                          {"false_hit_pct", pct(c.falseHit, c.evaluated)},
                          {"ambiguous_pct", pct(c.ambiguous, c.evaluated + c.ambiguous)}};
  };
  nlohmann::json out = split(error.total);
  out["opaque"] = split(error.opaque);
  out["translucent"] = split(error.translucent);
  out["sky_leak_pixels"] = error.skyLeakPixels;
  const char* names[4] = {"0-8", "8-32", "32-64", "64+"};
  for (std::size_t b = 0; b < 4; ++b) out["by_distance"][names[b]] = split(error.byDistance[b]);
  return out;
}

}  // namespace terrasol
