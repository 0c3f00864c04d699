#include "core/tint_palette.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace terrasol {
namespace {

Colormap solid(glm::vec3 srgb) {
  Colormap map{1, 1, {}};
  for (int c = 0; c < 3; ++c) map.rgb.push_back(static_cast<std::uint8_t>(std::lround(srgb[c] * 255.0f)));
  return map;
}

glm::vec3 texel(const Colormap& map, int x, int y) {
  const std::size_t i = static_cast<std::size_t>(std::clamp(y, 0, map.height - 1) * map.width +
                                                 std::clamp(x, 0, map.width - 1)) *
                        3;
  return {map.rgb[i], map.rgb[i + 1], map.rgb[i + 2]};
}

glm::u8vec3 bytes(glm::vec3 c) {
  return glm::u8vec3(glm::clamp(glm::round(c), glm::vec3(0.0f), glm::vec3(255.0f)));
}

// The climate's texel, (255 - temperature, 255 - downfall) on a 256 x 256 map (as most packs' are):
// bilinear between texel centres on maps of other sizes.
glm::u8vec3 lookUp(const Colormap& map, TintClimate climate) {
  if (map.width == 256 && map.height == 256) {
    const std::size_t i =
        static_cast<std::size_t>((255 - climate.downfall) * 256 + 255 - climate.temperature) * 3;
    return {map.rgb[i], map.rgb[i + 1], map.rgb[i + 2]};
  }
  const float x = static_cast<float>(255 - climate.temperature) / 255.0f * static_cast<float>(map.width - 1);
  const float y = static_cast<float>(255 - climate.downfall) / 255.0f * static_cast<float>(map.height - 1);
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const glm::vec3 top = texel(map, x0, y0) * (1.0f - fx) + texel(map, x0 + 1, y0) * fx;
  const glm::vec3 bottom = texel(map, x0, y0 + 1) * (1.0f - fx) + texel(map, x0 + 1, y0 + 1) * fx;
  return bytes(top * (1.0f - fy) + bottom * fy);
}

// The biome's own colour laid over `base` by its weight, rounded.
glm::u8vec3 over(glm::u8vec3 base, BiomeColour own) {
  if (own.weight == 0) return base;
  const auto mix = [&](int from, int to) {
    return static_cast<std::uint8_t>((from * (255 - own.weight) + to * own.weight + 127) / 255);
  };
  return {mix(base.r, own.r), mix(base.g, own.g), mix(base.b, own.b)};
}

}  // namespace

TintPalette::TintPalette() : TintPalette({}, {}) {}

TintPalette::TintPalette(Colormap grass, Colormap foliage)
    : grass_(grass.rgb.empty() ? solid(kDefaultGrass) : std::move(grass)),
      foliage_(foliage.rgb.empty() ? solid(kDefaultFoliage) : std::move(foliage)) {}

glm::u8vec3 TintPalette::rgb(Tint tint, const ColumnTint& column) const {
  switch (tint) {
    case Tint::None:
      return glm::u8vec3(255);
    case Tint::Grass:
      return over(lookUp(grass_, column.climate), column.grass);
    case Tint::Foliage:
      return over(lookUp(foliage_, column.climate), column.foliage);
    case Tint::Water:
      return over(bytes(waterTint(column.climate.temperature) * 255.0f), column.water);
    case Tint::Birch:
      return bytes(kBirchFoliage * 255.0f);
    case Tint::Spruce:
      return bytes(kSpruceFoliage * 255.0f);
  }
  return glm::u8vec3(255);
}

glm::vec3 TintPalette::colour(Tint tint, const ColumnTint& column) const {
  return glm::vec3(rgb(tint, column)) / 255.0f;
}

}  // namespace terrasol
