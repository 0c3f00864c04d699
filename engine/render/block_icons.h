#pragma once
// Inventory icons: each block drawn alone by the engine, from its model and the loaded packs'
// textures (tinted as in the plains), isometric as Minecraft's inventory shows it, lit from above,
// into one texture of square cells. Drawn once when made; remade when the packs change. GL thread only.

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "assets/atlas.h"
#include "assets/image.h"
#include "assets/shader_source.h"
#include "core/tint_palette.h"
#include "mesh/mesh_data.h"
#include "render/gl/object.h"

namespace terrasol {

class BlockIcons {
 public:
  // `meshes`: one per icon (mesh/block_icon_mesh.h). `cell`: pixels per icon side.
  BlockIcons(const ShaderPreprocessor& shaders, const Atlas& atlas, const TintPalette& tints,
             const std::vector<SectionMesh>& meshes, int cell);

  GLuint texture() const { return texture_.id(); }
  // Icon i's corners in the texture (u0, v0, u1, v1), v = 0 at the top row, as ImGui takes them.
  glm::vec4 uv(std::size_t icon) const;
  std::size_t count() const { return count_; }
  // The whole sheet, top row first, straight alpha (transparent around each block).
  Image read() const;

 private:
  std::size_t count_;
  int cell_, columns_;
  glm::ivec2 size_;
  gl::Texture texture_;
  gl::Renderbuffer depth_;
  gl::Framebuffer framebuffer_;
};

}  // namespace terrasol
