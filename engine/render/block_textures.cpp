#include "render/block_textures.h"

#include <cmath>

#include "render/gl_slots.h"

namespace terrasol {
namespace {

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
glm::vec3 srgbToLinear(glm::vec3 c) {
  return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)};
}

}  // namespace

BlockTextures::BlockTextures(const Atlas& atlas, const TintPalette& tints)
    : textures_(atlas),
      tiles_(gl::Buffer::create()),
      entries_(atlas.textures),
      current_(atlas.textures.size()),
      grid_(atlas.columns, atlas.slotSize, atlas.tileSize),
      size_(static_cast<float>(atlas.columns * atlas.slotSize),
            static_cast<float>(atlas.rows * atlas.slotSize)),
      waterTint_(srgbToLinear(tints.colour(Tint::Water))) {
  for (std::size_t i = 0; i < entries_.size(); ++i)
    current_[i] = static_cast<std::uint32_t>(entries_[i].firstTile);
  if (current_.empty()) current_.push_back(0);  // a storage buffer may not be empty
  glNamedBufferStorage(tiles_.id(), static_cast<GLsizeiptr>(current_.size() * sizeof(std::uint32_t)),
                       current_.data(), GL_DYNAMIC_STORAGE_BIT);
}

void BlockTextures::update(std::int64_t ticks) {
  bool changed = false;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (!entries_[i].animation) continue;
    // Interpolated animations show their nearer frame: the atlas holds frames, not blends.
    const FrameBlend f = frameAt(*entries_[i].animation, ticks);
    const auto tile = static_cast<std::uint32_t>(entries_[i].firstTile + (f.blend < 0.5f ? f.frame : f.next));
    changed |= tile != current_[i];
    current_[i] = tile;
  }
  if (changed) {
    glNamedBufferSubData(tiles_.id(), 0, static_cast<GLsizeiptr>(current_.size() * sizeof(std::uint32_t)),
                         current_.data());
  }
}

void BlockTextures::bind(const AtlasUniforms& uniforms) const {
  glBindTextureUnit(slots::kUnitAtlasAlbedo, textures_.albedo());
  glBindTextureUnit(slots::kUnitAtlasNormal, textures_.normal());
  glBindTextureUnit(slots::kUnitAtlasSpecular, textures_.specular());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slots::kStorageTiles, tiles_.id());
  uniforms.grid.set(grid_);
  uniforms.size.set(size_);
  uniforms.detail.set(detail_);
}

}  // namespace terrasol
