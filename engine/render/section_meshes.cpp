#include "render/section_meshes.h"

#include <vector>

#include "render/gl_slots.h"

namespace terrasol {

SectionMeshes::SectionMeshes() : layout_(gl::VertexArray::create()) {
  glEnableVertexArrayAttrib(layout_.id(), slots::kAttribPacked);
  glVertexArrayAttribIFormat(layout_.id(), slots::kAttribPacked, 4, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(layout_.id(), slots::kAttribPacked, 0);
}

void SectionMeshes::upload(const SectionMesh& mesh) {
  ++generation_;
  if (mesh.empty()) {
    remove(mesh.pos);
    return;
  }
  Section section;
  for (int l = 0; l < kMeshLayers; ++l) {
    const MeshData& data = mesh.layers[static_cast<std::size_t>(l)];
    if (data.vertices.empty()) continue;
    Layer& layer = section.layers[static_cast<std::size_t>(l)];
    layer.vertices = gl::Buffer::create();
    glNamedBufferStorage(layer.vertices.id(), static_cast<GLsizeiptr>(data.vertices.size() * sizeof(PackedVertex)),
                         data.vertices.data(), 0);
    layer.quads = static_cast<GLsizei>(data.quads());
    ensureIndices(layer.quads);
  }
  sections_[mesh.pos] = std::move(section);
}

void SectionMeshes::remove(SectionPos pos) {
  sections_.erase(pos);
  ++generation_;
}

void SectionMeshes::bindLayer(const Layer& layer) const {
  glVertexArrayVertexBuffer(layout_.id(), 0, layer.vertices.id(), 0, sizeof(PackedVertex));
}

// Quad q uses vertices 4q..4q+3 as triangles (0 1 2) (0 2 3): mesh_data.h's contract.
void SectionMeshes::ensureIndices(GLsizei quads) {
  if (quads <= indexQuads_) return;
  GLsizei count = indexQuads_ ? indexQuads_ : 4096;
  while (count < quads) count *= 2;
  std::vector<GLuint> data;
  data.reserve(static_cast<std::size_t>(count) * 6);
  for (GLuint q = 0; q < static_cast<GLuint>(count); ++q) {
    for (GLuint i : {0u, 1u, 2u, 0u, 2u, 3u}) data.push_back(q * 4 + i);
  }
  indices_ = gl::Buffer::create();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(data.size() * sizeof(GLuint)), data.data(), 0);
  glVertexArrayElementBuffer(layout_.id(), indices_.id());
  indexQuads_ = count;
}

}  // namespace terrasol
