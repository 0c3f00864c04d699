#pragma once
// Section meshes on the GPU: one immutable vertex buffer per section and layer, replaced whole when
// the section is remeshed (no holes, no flicker), drawn as quads through one shared index buffer.
// GL thread only.

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "mesh/mesh_data.h"
#include "render/gl/object.h"

namespace terrasol {

class SectionMeshes {
 public:
  SectionMeshes();

  // Replaces the section's mesh; an empty mesh removes it. Either way its face links are kept.
  void upload(const SectionMesh& mesh);
  // The face links of a section (all linked when never told otherwise).
  FaceLinks faceLinks(SectionPos pos) const {
    const auto it = links_.find(pos);
    return it == links_.end() ? kAllFacesLinked : it->second;
  }
  void remove(SectionPos pos);
  void clear() {
    sections_.clear();
    links_.clear();
    ++generation_;
  }
  // Changes with every upload, removal or clear: what was drawn from the meshes may be reused until then.
  std::uint64_t generation() const { return generation_; }

  // Opaque and cutout quads are stored grouped by the face they show (Direction order, then everything
  // else: cross plants), so a pass can leave out whole groups that face away from the camera.
  static constexpr int kFaceGroups = 7;
  struct Layer {
    gl::Buffer vertices;
    GLsizei quads = 0;
    std::array<GLsizei, kFaceGroups + 1> groupStart{};  // quad index of each group; [7] = quads
  };
  struct Section {
    std::array<Layer, kMeshLayers> layers;
  };
  // In a fixed order, so frames are reproducible.
  const std::map<SectionPos, Section>& sections() const { return sections_; }

  // The vertex array: attribute ATTRIB_PACKED from binding 0, and the quad index buffer. Point
  // binding 0 at a layer's buffer with bindLayer() before drawing it.
  GLuint vertexArray() const { return layout_.id(); }
  void bindLayer(const Layer& layer) const;

 private:
  void ensureIndices(GLsizei quads);
  const PackedVertices& groupByFace(const MeshData& data, std::array<GLsizei, kFaceGroups + 1>& start);

  std::map<SectionPos, Section> sections_;
  gl::VertexArray layout_;
  gl::Buffer indices_;
  GLsizei indexQuads_ = 0;
  std::uint64_t generation_ = 0;
  PackedVertices grouped_;  // reused by upload
  std::map<SectionPos, FaceLinks> links_;  // only sections not linked all round
};

}  // namespace terrasol
