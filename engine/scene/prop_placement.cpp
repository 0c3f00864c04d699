#include "scene/prop_placement.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/light_level.h"

namespace terrasol {

PropTransform propTransform(const SceneProp& prop) {
  return propTransform(prop.position, prop.rotation, prop.scale);
}

PropTransform propTransform(const glm::dvec3& position, const glm::vec3& rotationDegrees, float scale) {
  const glm::vec3 r = glm::radians(rotationDegrees);
  glm::mat4 m = glm::rotate(glm::mat4(1.0f), r.x, glm::vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, r.y, glm::vec3(1.0f, 0.0f, 0.0f));
  m = glm::rotate(m, r.z, glm::vec3(0.0f, 0.0f, 1.0f));
  PropTransform t;
  t.position = position;
  t.rotation = glm::mat3(m);
  t.basis = t.rotation * scale;
  return t;
}

glm::dvec3 toWorld(const PropTransform& t, const glm::vec3& modelPoint) {
  return t.position + glm::dvec3(t.basis * modelPoint);
}

WorldBounds placedBounds(const PropTransform& t, const glm::vec3& min, const glm::vec3& max) {
  WorldBounds b{glm::dvec3(INFINITY), glm::dvec3(-INFINITY)};
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y, corner & 4 ? max.z : min.z);
    const glm::dvec3 w = toWorld(t, p);
    b.min = glm::min(b.min, w);
    b.max = glm::max(b.max, w);
  }
  return b;
}

std::vector<glm::vec2> smoothLightAt(const World& world, const LightEngine& light,
                                     std::span<const glm::dvec3> points) {
  const auto& opacity = world.blocks().opacities();
  std::vector<glm::vec2> out;
  out.reserve(points.size());
  for (const glm::dvec3& p : points) {
    // Cell centres sit at n + 0.5: the 8 around p start at floor(p - 0.5).
    const glm::dvec3 q = p - 0.5;
    const glm::dvec3 base = glm::floor(q);
    const glm::dvec3 f = q - base;
    glm::vec2 sum(0.0f);
    double weights = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const BlockPos cell{static_cast<int>(base.x) + (corner & 1),
                          static_cast<int>(base.y) + (corner >> 1 & 1),
                          static_cast<int>(base.z) + (corner >> 2 & 1)};
      if (opacity[world.getBlock(cell)] >= kMaxLight) continue;  // stops all light
      const double w =
          (corner & 1 ? f.x : 1.0 - f.x) * (corner & 2 ? f.y : 1.0 - f.y) * (corner & 4 ? f.z : 1.0 - f.z);
      sum += static_cast<float>(w) *
             glm::vec2(light.lightAt(cell, LightChannel::Block), light.lightAt(cell, LightChannel::Sky));
      weights += w;
    }
    out.push_back(weights > 1e-9 ? sum / static_cast<float>(weights * kMaxLight) : glm::vec2(0.0f));
  }
  return out;
}

std::vector<glm::vec2> modelLight(const Model& model, const PropTransform& t, const World& world,
                                  const LightEngine& light) {
  std::vector<glm::dvec3> points;
  points.reserve(model.vertexCount());
  for (const ModelMesh& mesh : model.meshes) {
    for (const ModelVertex& v : mesh.vertices) points.push_back(toWorld(t, v.position));
  }
  return smoothLightAt(world, light, points);
}

int ModelCache::load(const std::filesystem::path& file) {
  const auto known = std::find(files_.begin(), files_.end(), file);
  if (known != files_.end()) return static_cast<int>(known - files_.begin());
  models_.push_back(loadModel(file));
  files_.push_back(file);
  return static_cast<int>(models_.size()) - 1;
}

}  // namespace terrasol
