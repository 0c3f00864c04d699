#pragma once
// Everything the block passes sample besides the G-buffer: the three atlases, the tile each texture
// id shows this frame (animations advance it; a storage buffer the vertex shader indexes), the atlas
// grid and the biome colormaps. GL thread only.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "assets/atlas.h"
#include "assets/tints.h"
#include "render/atlas_textures.h"

namespace terrasol {

class BlockTextures {
 public:
  BlockTextures(const Atlas& atlas, const BiomeColormaps& colormaps);

  // Points every animated texture at its frame for world time `ticks`.
  void update(std::int64_t ticks);
  // Binds the atlases, the colormaps and the tile buffer, and sets the atlas uniforms of `program`.
  void bind(GLuint program) const;
  const AtlasTextures& atlas() const { return textures_; }
  glm::vec3 waterTint() const { return waterTint_; }  // linear, at the plains' temperature

 private:
  AtlasTextures textures_;
  gl::Buffer tiles_;
  std::vector<AtlasTexture> entries_;  // per texture id: first tile and animation
  std::vector<std::uint32_t> current_;
  glm::ivec3 grid_;   // columns, slot size, tile size
  glm::vec2 size_;    // texels
  gl::Texture grassColormap_, foliageColormap_;
  glm::vec3 waterTint_;
};

}  // namespace terrasol
