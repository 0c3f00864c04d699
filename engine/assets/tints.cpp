#include "assets/tints.h"

#include <algorithm>

#include "core/error.h"

namespace terrasol {

glm::vec3 sampleColormap(const Image& colormap, float temperature, float downfall) {
  const float t = std::clamp(temperature, 0.0f, 1.0f);
  const float d = std::clamp(downfall, 0.0f, 1.0f) * t;
  const int x = std::clamp(static_cast<int>((1.0f - t) * static_cast<float>(colormap.width - 1)), 0, colormap.width - 1);
  const int y = std::clamp(static_cast<int>((1.0f - d) * static_cast<float>(colormap.height - 1)), 0, colormap.height - 1);
  const std::uint8_t* p = colormap.pixel(x, y);
  return glm::vec3(p[0], p[1], p[2]) / 255.0f;
}

BiomeTints loadTints(const PackStack& packs, std::vector<PackProblem>& problems, float temperature, float downfall) {
  BiomeTints tints{kDefaultGrass, kDefaultFoliage, kDefaultWater};
  auto fromMap = [&](const char* name, glm::vec3& out) {
    const std::string path = std::string("assets/minecraft/textures/colormap/") + name;
    try {
      const auto found = packs.find(path);
      if (!found) return;
      const std::string shown = found->pack->files().displayName(path);
      out = sampleColormap(decodeImage(found->pack->files().require(path), shown, kTextureLimits), temperature, downfall);
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Error, e.what()});
    }
  };
  fromMap("grass.png", tints.grass);
  fromMap("foliage.png", tints.foliage);
  return tints;
}

}  // namespace terrasol
