#pragma once
// The colours tinted blocks take from a pack: its grass and foliage colormaps looked up where a
// column's climate places it, under the column's biome colours (ColumnTint), water by temperature,
// Minecraft's fixed birch and spruce leaves. The mesher writes these into vertices (sRGB bytes, as
// Minecraft's vertex colours); the tools that draw blocks on the CPU read the same.

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/tint.h"

namespace terrasol {

// A colormap as packs ship it (assets/minecraft/textures/colormap/*.png): sRGB, RGB8 rows.
struct Colormap {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

class TintPalette {
 public:
  // Without colormaps: Minecraft's plains grass and foliage at every climate.
  TintPalette();
  // An empty map (0 x 0) falls back as above.
  TintPalette(Colormap grass, Colormap foliage);

  // sRGB 0..255; white for Tint::None.
  glm::u8vec3 rgb(Tint tint, const ColumnTint& column = kPlainsColumn) const;
  // The same, 0..1.
  glm::vec3 colour(Tint tint, const ColumnTint& column = kPlainsColumn) const;

  const Colormap& grass() const { return grass_; }
  const Colormap& foliage() const { return foliage_; }

 private:
  Colormap grass_, foliage_;
};

}  // namespace terrasol
