#pragma once
// Section meshes on the GPU: one immutable vertex buffer per section and layer, replaced whole when
// the section is remeshed (no holes, no flicker), drawn as quads through one shared index buffer.
// GL thread only.

#include <array>
#include <cstdint>
#include <map>
#include <utility>
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
  // else: cross plants), so a pass can leave out whole groups that face away from the camera; the
  // translucent layer is one group in the mesher's order. Within a group: the faces only the light's
  // view draws, the quads both draw, the merged quads only the camera's view draws (QuadRole), so
  // either view of a group is one run of quads.
  static constexpr int kFaceGroups = 7;
  enum class View { Camera, Light };
  struct Layer {
    gl::Buffer vertices;
    GLsizei quads = 0;
    std::array<GLsizei, kFaceGroups * kQuadRoles + 1> start{};  // first quad of each group's role runs

    // Quads [first, second) of `group` as `view` draws them.
    std::pair<GLsizei, GLsizei> range(int group, View view) const {
      const auto run = static_cast<std::size_t>(group * kQuadRoles + (view == View::Camera ? 1 : 0));
      return {start[run], start[run + 2]};
    }
  };
  struct Section {
    std::array<Layer, kMeshLayers> layers;
    std::vector<std::uint16_t> textures;  // the texture ids of its opaque and cutout quads, each once
  };
  // In a fixed order, so frames are reproducible.
  const std::map<SectionPos, Section>& sections() const { return sections_; }

  // The vertex array: attribute ATTRIB_PACKED from binding 0, and the quad index buffer. Point
  // binding 0 at a layer's buffer with bindLayer() before drawing it.
  GLuint vertexArray() const { return layout_.id(); }
  void bindLayer(const Layer& layer) const;

 private:
  void ensureIndices(GLsizei quads);
  const PackedVertices& group(const MeshData& data, bool byFace,
                              std::array<GLsizei, kFaceGroups * kQuadRoles + 1>& start);

  std::map<SectionPos, Section> sections_;
  gl::VertexArray layout_;
  gl::Buffer indices_;
  GLsizei indexQuads_ = 0;
  std::uint64_t generation_ = 0;
  PackedVertices grouped_;                 // reused by upload
  std::map<SectionPos, FaceLinks> links_;  // only sections not linked all round
};

}  // namespace terrasol
