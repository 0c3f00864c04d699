#include "render/lod_meshes.h"

#include <algorithm>
#include <cstddef>

#include "render/gl_slots.h"

namespace terrasol {

LodMeshes::LodMeshes() : layout_(gl::VertexArray::create()) {
  const GLuint vao = layout_.id();
  glEnableVertexArrayAttrib(vao, slots::kAttribLodCorner);
  glVertexArrayAttribIFormat(vao, slots::kAttribLodCorner, 3, GL_SHORT, offsetof(LodVertex, x));
  glEnableVertexArrayAttrib(vao, slots::kAttribLodCell);
  glVertexArrayAttribIFormat(vao, slots::kAttribLodCell, 2, GL_UNSIGNED_BYTE, offsetof(LodVertex, cellX));
  glEnableVertexArrayAttrib(vao, slots::kAttribLodMaterial);
  glVertexArrayAttribIFormat(vao, slots::kAttribLodMaterial, 1, GL_UNSIGNED_INT,
                             offsetof(LodVertex, material));
  for (const int a : {slots::kAttribLodCorner, slots::kAttribLodCell, slots::kAttribLodMaterial})
    glVertexArrayAttribBinding(vao, static_cast<GLuint>(a), 0);
  setFullDetail(glm::ivec2(0), 1, {0});
}

void LodMeshes::show(const LodSet& set) {
  std::vector<Tile> next;
  next.reserve(set.meshes.size());
  GLsizei most = 0;
  for (const std::shared_ptr<const LodMesh>& mesh : set.meshes) {
    const auto kept =
        std::find_if(tiles_.begin(), tiles_.end(), [&](const Tile& t) { return t.mesh == mesh; });
    if (kept != tiles_.end()) {
      next.push_back(std::move(*kept));
      continue;
    }
    Tile tile{mesh, {}, {}, 0, 0};
    if (!mesh->indices.empty())
      tile.triangles = static_cast<GLsizei>(mesh->indices.size() / 3);
    else
      tile.quads = static_cast<GLsizei>(mesh->vertices.size() / 4);
    if (tile.quads > 0 || tile.triangles > 0) {
      tile.vertices = gl::Buffer::create();
      glNamedBufferStorage(tile.vertices.id(),
                           static_cast<GLsizeiptr>(mesh->vertices.size() * sizeof(LodVertex)),
                           mesh->vertices.data(), 0);
    }
    if (tile.triangles > 0) {
      tile.indices = gl::Buffer::create();
      glNamedBufferStorage(tile.indices.id(),
                           static_cast<GLsizeiptr>(mesh->indices.size() * sizeof(std::uint16_t)),
                           mesh->indices.data(), 0);
    }
    most = std::max(most, tile.quads);
    next.push_back(std::move(tile));
  }
  tiles_ = std::move(next);
  ++generation_;
  if (most <= indexQuads_) return;
  // Quad q uses vertices 4q..4q+3 as triangles (0 1 2) (0 2 3), as the section meshes do.
  GLsizei count = std::max<GLsizei>(indexQuads_, 4096);
  while (count < most) count *= 2;
  std::vector<GLuint> data;
  data.reserve(static_cast<std::size_t>(count) * 6);
  for (GLuint q = 0; q < static_cast<GLuint>(count); ++q)
    for (const GLuint i : {0u, 1u, 2u, 0u, 2u, 3u}) data.push_back(q * 4 + i);
  indices_ = gl::Buffer::create();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(data.size() * sizeof(GLuint)), data.data(), 0);
  indexQuads_ = count;
}

void LodMeshes::clear() {
  tiles_.clear();
  ++generation_;
}

void LodMeshes::setFullDetail(glm::ivec2 origin, int size, const std::vector<std::uint8_t>& covered) {
  size = std::max(size, 1);
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(size * size), 0);
  std::copy_n(covered.begin(), std::min(covered.size(), texels.size()), texels.begin());
  if (size != maskSize_) {
    mask_ = gl::Texture::create(GL_TEXTURE_2D);
    glTextureStorage2D(mask_.id(), 1, GL_R8UI, size, size);
    // An integer texture is complete only with nearest filtering; texelFetch of an incomplete one reads 0.
    glTextureParameteri(mask_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(mask_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    maskSize_ = size;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(mask_.id(), 0, 0, 0, size, size, GL_RED_INTEGER, GL_UNSIGNED_BYTE, texels.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  maskOrigin_ = origin;
}

std::size_t LodMeshes::gpuBytes() const {
  std::size_t bytes = static_cast<std::size_t>(indexQuads_) * 6 * sizeof(GLuint) +
                      static_cast<std::size_t>(maskSize_ * maskSize_);
  for (const Tile& t : tiles_)
    bytes += t.mesh->vertices.size() * sizeof(LodVertex) + t.mesh->indices.size() * sizeof(std::uint16_t);
  return bytes;
}

void LodMeshes::bindTile(const Tile& tile) const {
  glVertexArrayVertexBuffer(layout_.id(), 0, tile.vertices.id(), 0, sizeof(LodVertex));
  glVertexArrayElementBuffer(layout_.id(), tile.triangles > 0 ? tile.indices.id() : indices_.id());
}

}  // namespace terrasol
