#include "assets/model_bake.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/model_units.h"

namespace terrasol {
namespace {

// The point of an element's face where the default uv is (u0 or u1, v0 or v1): `s` picks u1, `t` v1.
// Inverts defaultUv (block_model.cpp): u and v run across the face as seen from outside.
glm::vec3 faceCorner(ModelFace face, glm::vec3 from, glm::vec3 to, bool s, bool t) {
  switch (face) {
    case ModelFace::Down:
      return {s ? to.x : from.x, from.y, t ? from.z : to.z};
    case ModelFace::Up:
      return {s ? to.x : from.x, to.y, t ? to.z : from.z};
    case ModelFace::North:
      return {s ? from.x : to.x, t ? from.y : to.y, from.z};
    case ModelFace::South:
      return {s ? to.x : from.x, t ? from.y : to.y, to.z};
    case ModelFace::West:
      return {from.x, t ? from.y : to.y, s ? to.z : from.z};
    case ModelFace::East:
      return {to.x, t ? from.y : to.y, s ? from.z : to.z};
  }
  return from;
}

// Where a point lies in a face's default uv (1/16 units): defaultUv's mapping, for uvlock.
glm::vec2 lockedUv(ModelFace face, glm::vec3 p) {
  constexpr float kUnits = kModelUnits;
  switch (face) {
    case ModelFace::Down:
      return {p.x, kUnits - p.z};
    case ModelFace::Up:
      return {p.x, p.z};
    case ModelFace::North:
      return {kUnits - p.x, kUnits - p.y};
    case ModelFace::South:
      return {p.x, kUnits - p.y};
    case ModelFace::West:
      return {p.z, kUnits - p.y};
    case ModelFace::East:
      return {kUnits - p.z, kUnits - p.y};
  }
  return {0.0f, 0.0f};
}

// Turns `v` by `degrees` about axis 0, 1 or 2 (right-handed).
glm::vec3 turn(glm::vec3 v, int axis, float degrees) {
  const float a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  switch (axis) {
    case 0:
      return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
    case 1:
      return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
    default:
      return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
  }
}

// Exact for right angles: no drift from sin and cos of 90 degrees.
glm::vec3 turnRight(glm::vec3 v, int axis, int quarterTurns) {
  for (int i = 0; i < ((quarterTurns % 4) + 4) % 4; ++i) {
    switch (axis) {
      case 0:
        v = {v.x, -v.z, v.y};
        break;
      case 1:
        v = {v.z, v.y, -v.x};
        break;
      default:
        v = {-v.y, v.x, v.z};
        break;
    }
  }
  return v;
}

// A blockstate's x then y, about the block's centre: Minecraft turns clockwise looking along +x and
// looking down (y = 90 takes north to east; x = 90 takes up to north).
glm::vec3 place(glm::vec3 v, const ModelPlacement& p, bool isPoint) {
  const glm::vec3 centre = isPoint ? glm::vec3(8.0f) : glm::vec3(0.0f);
  v -= centre;
  v = turnRight(v, 0, -p.x / 90);
  v = turnRight(v, 1, -p.y / 90);
  return v + centre;
}

}  // namespace

std::vector<std::array<float, 6>> placedBoxes(const BlockModel& model, const ModelPlacement& placement) {
  std::vector<std::array<float, 6>> boxes;
  for (const ModelElement& e : model.elements) {
    if (e.rotation && e.rotation->angle != 0.0f) continue;
    const glm::vec3 a = place(e.from, placement, true), b = place(e.to, placement, true);
    const glm::vec3 lo = glm::min(a, b), hi = glm::max(a, b);
    boxes.push_back({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  }
  return boxes;
}

ModelFace nearestFace(glm::vec3 normal) {
  ModelFace best = ModelFace::Up;
  float bestDot = -2.0f;
  for (int f = 0; f < 6; ++f) {
    const float d = glm::dot(normal, faceNormal(static_cast<ModelFace>(f)));
    if (d > bestDot + 1e-6f) {
      bestDot = d;
      best = static_cast<ModelFace>(f);
    }
  }
  return best;
}

std::vector<BakedQuad> bakeModel(const BlockModel& model, const ModelPlacement& placement) {
  std::vector<BakedQuad> quads;
  for (const ModelElement& e : model.elements) {
    const bool turned = e.rotation && e.rotation->angle != 0.0f;
    for (int f = 0; f < 6; ++f) {
      const std::optional<ElementFace>& spec = e.faces[static_cast<std::size_t>(f)];
      if (!spec) continue;
      const ModelFace face = static_cast<ModelFace>(f);
      BakedQuad q;
      q.texture = spec->texture;
      q.tintIndex = spec->tintIndex;
      q.shade = e.shade;
      q.ambientOcclusion = model.ambientOcclusion && !turned;
      glm::vec3 normal = faceNormal(face);
      std::array<glm::vec3, 4> corners = {
          faceCorner(face, e.from, e.to, false, false), faceCorner(face, e.from, e.to, false, true),
          faceCorner(face, e.from, e.to, true, true), faceCorner(face, e.from, e.to, true, false)};
      if (turned) {
        const ElementRotation& r = *e.rotation;
        const float stretch = r.rescale ? 1.0f / std::cos(glm::radians(std::abs(r.angle))) : 1.0f;
        for (glm::vec3& c : corners) {
          glm::vec3 d = turn(c - r.origin, r.axis, r.angle);
          for (int i = 0; i < 3; ++i) {
            if (i != r.axis) d[i] *= stretch;
          }
          c = r.origin + d;
        }
        normal = turn(normal, r.axis, r.angle);
      }
      for (glm::vec3& c : corners) c = place(c, placement, true);
      normal = place(normal, placement, false);
      q.normal = glm::normalize(normal);
      q.face = nearestFace(q.normal);
      if (spec->cullface) q.cullface = nearestFace(place(faceNormal(*spec->cullface), placement, false));

      const glm::vec4 uv = spec->uv;
      std::array<glm::vec2, 4> uvs = {glm::vec2(uv.x, uv.y), glm::vec2(uv.x, uv.w), glm::vec2(uv.z, uv.w),
                                      glm::vec2(uv.z, uv.y)};
      const bool placed = placement.x != 0 || placement.y != 0;
      if (placement.uvlock && placed && !turned) {
        // The texture stays put in the world: read each corner's uv where it now lies.
        for (std::size_t i = 0; i < 4; ++i) uvs[i] = lockedUv(q.face, corners[i]);
      }
      const int shift = spec->rotation / 90;
      for (std::size_t i = 0; i < 4; ++i) {
        q.uvs[i] = uvs[(i + static_cast<std::size_t>(shift)) % 4] / static_cast<float>(kModelUnits);
        q.corners[i] = corners[i] / static_cast<float>(kModelUnits);
      }
      quads.push_back(std::move(q));
    }
  }
  return quads;
}

}  // namespace terrasol
