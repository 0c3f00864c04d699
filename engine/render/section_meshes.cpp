#include "render/section_meshes.h"

#include <algorithm>
#include <vector>

#include "render/gl_slots.h"

namespace terrasol {

namespace {

// The run a quad is stored in: its face group (or the last group), then its role, light-only first.
std::size_t runOf(const PackedVertex& v, bool byFace) {
  const int group = byFace && v.face() < 6 ? v.face() : SectionMeshes::kFaceGroups - 1;
  constexpr int kSlot[kQuadRoles] = {1, 0, 2};  // Both, Faces, Merged
  return static_cast<std::size_t>(group * kQuadRoles + kSlot[static_cast<int>(v.role())]);
}

}  // namespace

// A stable counting sort of the quads into their runs; `start` receives each run's first quad.
const PackedVertices& SectionMeshes::group(const MeshData& data, bool byFace,
                                           std::array<GLsizei, kFaceGroups * kQuadRoles + 1>& start) {
  start.fill(0);
  for (std::size_t q = 0; q < data.quads(); ++q) ++start[runOf(data.vertices[q * 4], byFace) + 1];
  for (std::size_t r = 0; r + 1 < start.size(); ++r) start[r + 1] += start[r];
  grouped_.resize(data.vertices.size());
  auto next = start;
  for (std::size_t q = 0; q < data.quads(); ++q) {
    const auto at = static_cast<std::size_t>(next[runOf(data.vertices[q * 4], byFace)]++);
    std::copy_n(data.vertices.begin() + static_cast<std::ptrdiff_t>(q * 4), 4,
                grouped_.begin() + static_cast<std::ptrdiff_t>(at * 4));
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
  for (const MeshLayer l : {MeshLayer::Opaque, MeshLayer::Cutout}) {
    const PackedVertices& vertices = mesh.layers[static_cast<std::size_t>(l)].vertices;
    for (std::size_t v = 0; v < vertices.size(); v += 4) {
      const auto texture = static_cast<std::uint16_t>(vertices[v].texture());
      if (std::find(section.textures.begin(), section.textures.end(), texture) == section.textures.end()) {
        section.textures.push_back(texture);
      }
    }
  }
  for (int l = 0; l < kMeshLayers; ++l) {
    const MeshData& data = mesh.layers[static_cast<std::size_t>(l)];
    if (data.vertices.empty()) continue;
    Layer& layer = section.layers[static_cast<std::size_t>(l)];
    layer.quads = static_cast<GLsizei>(data.quads());
    // Translucent quads keep the mesher's order (blending within a section depends on it): one group.
    const PackedVertices& vertices =
        group(data, static_cast<MeshLayer>(l) != MeshLayer::Translucent, layer.start);
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
