#include "render/section_draw.h"

#include <algorithm>
#include <cstdint>

namespace terrasol {

std::vector<VisibleSection> sectionsInside(const FrustumPlanes& planes, glm::dvec3 camera,
                                           const SectionMeshes& meshes, int* outside) {
  std::vector<VisibleSection> inside;
  for (const auto& [pos, section] : meshes.sections()) {
    // In double: far from the origin a float cannot hold both the section and the small offset.
    const glm::dvec3 corner(pos.x * 16.0, kMinY + pos.section * 16.0, pos.z * 16.0);
    const glm::vec3 offset(corner - camera);
    if (boxVisible(planes, offset, 16.0f)) {
      inside.push_back({&section, offset, pos});
    } else if (outside) {
      ++*outside;
    }
  }
  return inside;
}

std::size_t quadsIn(const std::vector<VisibleSection>& sections, MeshLayer layer) {
  std::size_t quads = 0;
  for (const VisibleSection& v : sections) {
    quads += static_cast<std::size_t>(v.section->layers[static_cast<std::size_t>(layer)].quads);
  }
  return quads;
}

void drawSections(GLuint program, const SectionUniforms& uniforms, const BlockTextures& textures,
                  const std::vector<VisibleSection>& sections, const SectionMeshes& meshes, MeshLayer layer,
                  const SectionDraw& how) {
  struct Draw {
    const SectionMeshes::Layer* layer;
    glm::vec3 offset;
    float key;
  };
  const bool alongAxis = glm::dot(how.axis, how.axis) > 0.0f;
  std::vector<Draw> draws;
  for (const VisibleSection& v : sections) {
    const auto& l = v.section->layers[static_cast<std::size_t>(layer)];
    const glm::vec3 centre = v.offset + glm::vec3(8.0f);
    if (l.quads > 0)
      draws.push_back({&l, v.offset, alongAxis ? glm::dot(centre, how.axis) : glm::length(centre)});
  }
  if (draws.empty()) return;
  std::stable_sort(draws.begin(), draws.end(), [&](const Draw& a, const Draw& b) {
    return how.order == DrawOrder::NearestFirst ? a.key < b.key : a.key > b.key;
  });

  glUseProgram(program);
  textures.bind(uniforms.atlas);
  glBindVertexArray(meshes.vertexArray());
  for (const Draw& d : draws) {
    meshes.bindLayer(*d.layer);
    uniforms.offset.set(d.offset);
    // Face groups turned away from the camera for the whole section are never drawn: a face of normal
    // +x lies in a plane at x >= the section's corner, so it faces away from a camera (at 0) whenever
    // the corner's x >= 0; likewise for every direction. Runs of drawn groups become one range each.
    const glm::vec3 lo = d.offset, hi = d.offset + glm::vec3(16.0f);
    const bool away[SectionMeshes::kFaceGroups] = {hi.x <= 0.0f, lo.x >= 0.0f, hi.y <= 0.0f, lo.y >= 0.0f,
                                                   hi.z <= 0.0f, lo.z >= 0.0f, false};
    GLsizei counts[SectionMeshes::kFaceGroups];
    const void* offsets[SectionMeshes::kFaceGroups];
    GLsizei ranges = 0;
    for (int g = 0; g < SectionMeshes::kFaceGroups; ++g) {
      const auto [first, end] = d.layer->range(g, how.view);
      const GLsizei quads = end - first;
      if (quads == 0) continue;
      if (how.cullFacesAway && away[g]) {
        if (how.stats) how.stats->quadsFacingAway += quads;
        continue;
      }
      const auto offset =
          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 6 * sizeof(GLuint));
      if (ranges > 0 &&
          static_cast<const char*>(offsets[ranges - 1]) + counts[ranges - 1] * sizeof(GLuint) == offset) {
        counts[ranges - 1] += quads * 6;
      } else {
        counts[ranges] = quads * 6;
        offsets[ranges++] = offset;
      }
    }
    if (how.stats) {
      for (GLsizei r = 0; r < ranges; ++r) how.stats->quadsDrawn += counts[r] / 6;
    }
    if (ranges > 0) glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, offsets, ranges);
  }
  glBindVertexArray(0);
}

}  // namespace terrasol
