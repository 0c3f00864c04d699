#pragma once
// Far terrain on the GPU: one immutable vertex buffer per tile of the set shown (lod/lod_terrain.h),
// replaced a set at a time (a tile the next set keeps keeps its buffer): terraces drawn as quads through
// one shared index buffer, heightfields through their own; and the chunks full detail covers, as a mask the
// vertex shader lowers the far terrain's cells under. GL thread only.

#include <epoxy/gl.h>

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <vector>

#include "lod/lod_terrain.h"
#include "render/gl/object.h"

namespace terrasol {

class LodMeshes {
 public:
  LodMeshes();

  // Shows `set` from now on.
  void show(const LodSet& set);
  void clear();
  // Full detail covers chunk origin + (x, z) where covered[z * size + x] is not 0 (no other chunk).
  void setFullDetail(glm::ivec2 origin, int size, const std::vector<std::uint8_t>& covered);

  struct Tile {
    std::shared_ptr<const LodMesh> mesh;
    gl::Buffer vertices;
    gl::Buffer indices;     // a heightfield's triangles (terraces use the shared quad indices)
    GLsizei quads = 0;      // terraces
    GLsizei triangles = 0;  // a heightfield
  };
  const std::vector<Tile>& tiles() const { return tiles_; }  // nearest first
  bool empty() const { return tiles_.empty(); }
  std::uint64_t generation() const { return generation_; }
  std::size_t gpuBytes() const;

  // The vertex array (attributes ATTRIB_LOD_*); bindTile points it at a tile's vertices and indices.
  GLuint vertexArray() const { return layout_.id(); }
  void bindTile(const Tile& tile) const;
  GLuint fullDetailMask() const { return mask_.id(); }
  glm::ivec2 maskOrigin() const { return maskOrigin_; }
  int maskSize() const { return maskSize_; }

 private:
  std::vector<Tile> tiles_;
  gl::VertexArray layout_;
  gl::Buffer indices_;
  GLsizei indexQuads_ = 0;
  gl::Texture mask_;
  glm::ivec2 maskOrigin_{0};
  int maskSize_ = 0;
  std::uint64_t generation_ = 0;
};

}  // namespace terrasol
