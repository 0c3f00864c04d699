#pragma once
// Everything the block passes sample besides the G-buffer: the three atlases, the tile each texture
// id shows this frame (animations advance it; a storage buffer the vertex shader indexes), the atlas
// grid. GL thread only.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "assets/atlas.h"
#include "core/tint_palette.h"
#include "render/atlas_textures.h"
#include "render/gl/uniforms.h"

namespace terrasol {

// The atlas grid of a program that samples the atlas (lib/atlas_uv.glsl).
struct AtlasUniforms {
  AtlasUniforms() = default;
  explicit AtlasUniforms(const LinkedProgram& p)
      : grid(p, "u_atlasGrid"),
        size(p, "u_atlasSize"),
        // Only where the atlas is sampled (lib/atlas_sample.glsl), not in depth-only variants.
        detail(p.declares("u_textureDetail") ? gl::Uniform<float>(p, "u_textureDetail")
                                             : gl::Uniform<float>()) {}

  gl::Uniform<glm::ivec3> grid;
  gl::Uniform<glm::vec2> size;
  gl::Uniform<float> detail;
};

class BlockTextures {
 public:
  BlockTextures(const Atlas& atlas, const TintPalette& tints);

  // Points every animated texture at its frame for world time `ticks`.
  void update(std::int64_t ticks);
  // The footprint textures are read at: 1, or the render scale where TAA reconstructs the target's
  // detail (lib/atlas_sample.glsl).
  void setDetail(float detail) { detail_ = detail; }
  // Binds the atlases and the tile buffer, and sets a program's atlas uniforms.
  void bind(const AtlasUniforms& uniforms) const;
  const AtlasTextures& atlas() const { return textures_; }
  glm::vec3 waterTint() const { return waterTint_; }  // linear, at the plains' temperature

 private:
  AtlasTextures textures_;
  gl::Buffer tiles_;
  std::vector<AtlasTexture> entries_;  // per texture id: first tile and animation
  std::vector<std::uint32_t> current_;
  glm::ivec3 grid_;  // columns, slot size, tile size
  glm::vec2 size_;   // texels
  float detail_ = 1.0f;
  glm::vec3 waterTint_;
};

}  // namespace terrasol
