#include "assets/model_normals.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace terrasol {

glm::vec3 safeNormalize(glm::vec3 v, glm::vec3 fallback) {
  const float length = glm::length(v);
  return length > 1e-20f && std::isfinite(length) ? v / length : fallback;
}

void generateNormals(ModelMesh& mesh) {
  // Flat normals: each triangle gets its own three vertices.
  std::vector<ModelVertex> flat;
  flat.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    ModelVertex v[3] = {mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                        mesh.vertices[mesh.indices[t + 2]]};
    const glm::vec3 n =
        safeNormalize(glm::cross(v[1].position - v[0].position, v[2].position - v[0].position), {0, 1, 0});
    for (ModelVertex& x : v) {
      x.normal = n;
      flat.push_back(x);
    }
  }
  mesh.vertices = std::move(flat);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
  mesh.generatedNormals = true;
}

// Lengyel's per-triangle tangents from the UVs, summed per vertex and orthogonalised to the normal.
void generateTangents(ModelMesh& mesh, bool hasUv) {
  std::vector<glm::vec3> tan(mesh.vertices.size(), glm::vec3(0.0f)),
      bit(mesh.vertices.size(), glm::vec3(0.0f));
  if (hasUv) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
      const ModelVertex &a = mesh.vertices[i0], &b = mesh.vertices[i1], &c = mesh.vertices[i2];
      const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
      const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
      const float det = d1.x * d2.y - d2.x * d1.y;
      if (!(std::abs(det) > 1e-12f)) continue;  // no UV area: says nothing about the direction
      const glm::vec3 t3 = (e1 * d2.y - e2 * d1.y) / det, b3 = (e2 * d1.x - e1 * d2.x) / det;
      for (const std::uint32_t i : {i0, i1, i2}) {
        tan[i] += t3;
        bit[i] += b3;
      }
    }
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    ModelVertex& v = mesh.vertices[i];
    const glm::vec3 any = std::abs(v.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 fallback = safeNormalize(any - v.normal * glm::dot(v.normal, any), {1, 0, 0});
    const glm::vec3 t = safeNormalize(tan[i] - v.normal * glm::dot(v.normal, tan[i]), fallback);
    v.tangent = glm::vec4(t, glm::dot(glm::cross(v.normal, t), bit[i]) < 0.0f ? -1.0f : 1.0f);
  }
  mesh.generatedTangents = true;
}

}  // namespace terrasol
