#include "render/section_meshes.h"

#include <algorithm>
#include <vector>

#include "render/gl_slots.h"

namespace terrasol {

namespace {

int faceGroup(const PackedVertex& v) { return v.face() < 6 ? v.face() : SectionMeshes::kFaceGroups - 1; }

}  // namespace

// A counting sort of the quads by face group; `start` receives each group's first quad.
const PackedVertices& SectionMeshes::groupByFace(const MeshData& data, std::array<GLsizei, kFaceGroups + 1>& start) {
  start.fill(0);
  for (std::size_t q = 0; q < data.quads(); ++q) ++start[static_cast<std::size_t>(faceGroup(data.vertices[q * 4])) + 1];
  for (int g = 0; g < kFaceGroups; ++g) start[static_cast<std::size_t>(g) + 1] += start[static_cast<std::size_t>(g)];
  grouped_.resize(data.vertices.size());
  std::array<GLsizei, kFaceGroups + 1> next = start;
  for (std::size_t q = 0; q < data.quads(); ++q) {
    const auto at = static_cast<std::size_t>(next[static_cast<std::size_t>(faceGroup(data.vertices[q * 4]))]++);
    std::copy_n(data.vertices.begin() + static_cast<std::ptrdiff_t>(q * 4), 4, grouped_.begin() + static_cast<std::ptrdiff_t>(at * 4));
  }
  return grouped_;
}

SectionMeshes::SectionMeshes() : layout_(gl::VertexArray::create()) {
  glEnableVertexArrayAttrib(layout_.id(), slots::kAttribPacked);
  glVertexArrayAttribIFormat(layout_.id(), slots::kAttribPacked, 4, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(layout_.id(), slots::kAttribPacked, 0);
}

void SectionMeshes::upload(const SectionMesh& mesh) {
  ++generation_;
  if (mesh.faceLinks == kAllFacesLinked) {
    links_.erase(mesh.pos);
  } else {
    links_[mesh.pos] = mesh.faceLinks;
  }
  if (mesh.empty()) {
    remove(mesh.pos);
    return;
  }
  Section section;
  for (int l = 0; l < kMeshLayers; ++l) {
    const MeshData& data = mesh.layers[static_cast<std::size_t>(l)];
    if (data.vertices.empty()) continue;
    Layer& layer = section.layers[static_cast<std::size_t>(l)];
    layer.quads = static_cast<GLsizei>(data.quads());
    // Translucent quads keep the mesher's order (blending within a section depends on it): one group.
    const PackedVertices& vertices =
        static_cast<MeshLayer>(l) == MeshLayer::Translucent ? data.vertices : groupByFace(data, layer.groupStart);
    if (static_cast<MeshLayer>(l) == MeshLayer::Translucent) {
      layer.groupStart.fill(layer.quads);
      layer.groupStart[0] = 0;
    }
    layer.vertices = gl::Buffer::create();
    glNamedBufferStorage(layer.vertices.id(), static_cast<GLsizeiptr>(vertices.size() * sizeof(PackedVertex)),
                         vertices.data(), 0);
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
