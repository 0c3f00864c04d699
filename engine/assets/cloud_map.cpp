#include "assets/cloud_map.h"

#include "core/error.h"

namespace terrasol {

CloudMap loadCloudMap(const PackStack& packs, std::vector<PackProblem>& problems) {
  try {
    const auto found = packs.find(kCloudsTexture);
    if (!found) return {};
    const std::string shown = found->pack->files().displayName(kCloudsTexture);
    const Image image = decodeImage(found->pack->files().require(kCloudsTexture), shown, kTextureLimits);
    CloudMap map{image.width, image.height, {}};
    map.cover.reserve(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) map.cover.push_back(image.pixel(x, y)[3]);
    return map;
  } catch (const Error& e) {
    problems.push_back({PackProblem::Severity::Error, e.what()});
    return {};
  }
}

}  // namespace terrasol
