#include "assets/tints.h"

#include "core/error.h"

namespace terrasol {

Colormap colormapOf(const Image& image) {
  Colormap map{image.width, image.height, {}};
  map.rgb.reserve(static_cast<std::size_t>(image.width * image.height) * 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      map.rgb.insert(map.rgb.end(), p, p + 3);
    }
  return map;
}

TintPalette loadColormaps(const PackStack& packs, std::vector<PackProblem>& problems) {
  auto fromPack = [&](const char* name) -> Colormap {
    const std::string path = std::string("assets/minecraft/textures/colormap/") + name;
    try {
      const auto found = packs.find(path);
      if (!found) return {};
      const std::string shown = found->pack->files().displayName(path);
      return colormapOf(decodeImage(found->pack->files().require(path), shown, kTextureLimits));
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Error, e.what()});
      return {};
    }
  };
  Colormap grass = fromPack("grass.png");
  return TintPalette(std::move(grass), fromPack("foliage.png"));
}

}  // namespace terrasol
