#include "assets/tints.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace terrasol {
namespace {

Image solid(glm::vec3 srgb) {
  Image image(1, 1);
  for (int c = 0; c < 3; ++c)
    image.rgba[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(std::lround(srgb[c] * 255.0f));
  image.rgba[3] = 255;
  return image;
}

glm::vec3 texel(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
  return glm::vec3(p[0], p[1], p[2]) / 255.0f;
}

// Bilinear, between texel centres: the block shaders' sampler does the same.
glm::vec3 sampleAxes(const Image& map, float u, float v) {
  const float x = u * static_cast<float>(map.width - 1), y = v * static_cast<float>(map.height - 1);
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const glm::vec3 top = texel(map, x0, y0) * (1.0f - fx) + texel(map, x0 + 1, y0) * fx;
  const glm::vec3 bottom = texel(map, x0, y0 + 1) * (1.0f - fx) + texel(map, x0 + 1, y0 + 1) * fx;
  return top * (1.0f - fy) + bottom * fy;
}

}  // namespace

glm::vec3 sampleColormap(const Image& colormap, float temperature, float downfall) {
  const float t = std::clamp(temperature, 0.0f, 1.0f);
  const float d = std::clamp(downfall, 0.0f, 1.0f) * t;
  return texel(colormap, static_cast<int>((1.0f - t) * static_cast<float>(colormap.width - 1)),
               static_cast<int>((1.0f - d) * static_cast<float>(colormap.height - 1)));
}

BiomeColormaps loadColormaps(const PackStack& packs, std::vector<PackProblem>& problems) {
  BiomeColormaps maps{solid(kDefaultGrass), solid(kDefaultFoliage)};
  auto fromPack = [&](const char* name, Image& out) {
    const std::string path = std::string("assets/minecraft/textures/colormap/") + name;
    try {
      const auto found = packs.find(path);
      if (!found) return;
      const std::string shown = found->pack->files().displayName(path);
      out = decodeImage(found->pack->files().require(path), shown, kTextureLimits);
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Error, e.what()});
    }
  };
  fromPack("grass.png", maps.grass);
  fromPack("foliage.png", maps.foliage);
  return maps;
}

glm::vec3 tintColour(const BiomeColormaps& maps, Tint tint, TintClimate climate) {
  const float u = static_cast<float>(255 - climate.temperature) / 255.0f;
  const float v = static_cast<float>(255 - climate.downfall) / 255.0f;
  switch (tint) {
    case Tint::None:
      return glm::vec3(1.0f);
    case Tint::Grass:
      return sampleAxes(maps.grass, u, v);
    case Tint::Foliage:
      return sampleAxes(maps.foliage, u, v);
    case Tint::Water:
      return waterTint(climate.temperature);
    case Tint::Birch:
      return kBirchFoliage;
    case Tint::Spruce:
      return kSpruceFoliage;
  }
  return glm::vec3(1.0f);
}

}  // namespace terrasol
