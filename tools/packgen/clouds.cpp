// The default pack's cloud layer (textures/environment/clouds.png): white texels with alpha 255 where a
// cloud is and 0 where it is not, as Minecraft's map is, in blobs from a few texels to a few dozen
// across. Fractal noise made to repeat across the map's edges (the layer tiles the world), cut at
// the value that covers kCover of it.

#include <algorithm>
#include <vector>

#include "packgen.h"
#include "world/noise.h"

namespace terrasol::packgen {
namespace {

constexpr int kSide = 256;
constexpr double kCover = 0.35;    // Minecraft's map covers about a third of the sky
constexpr double kFeature = 18.0;  // texels across the noise's largest blobs
constexpr std::uint64_t kSeed = 20;

}  // namespace

Image generateClouds() {
  const Noise noise(kSeed);
  const double n = kSide;
  // Four copies of the noise shifted by a whole map, weighed so each edge meets the opposite one.
  auto tiled = [&](int x, int z) {
    const double u = x / n, v = z / n;
    auto at = [&](double dx, double dz) {
      return noise.fractal((x - dx) / kFeature, (z - dz) / kFeature, 3);
    };
    return at(0, 0) * (1 - u) * (1 - v) + at(n, 0) * u * (1 - v) + at(0, n) * (1 - u) * v + at(n, n) * u * v;
  };
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(kSide * kSide));
  for (int z = 0; z < kSide; ++z)
    for (int x = 0; x < kSide; ++x) values.push_back(tiled(x, z));
  std::vector<double> sorted = values;
  const auto cut =
      sorted.begin() + static_cast<std::ptrdiff_t>((1.0 - kCover) * static_cast<double>(sorted.size()));
  std::nth_element(sorted.begin(), cut, sorted.end());
  const double threshold = *cut;
  Image map(kSide, kSide);
  for (int z = 0; z < kSide; ++z)
    for (int x = 0; x < kSide; ++x) {
      std::uint8_t* p = map.pixel(x, z);
      p[0] = p[1] = p[2] = 255;
      p[3] = values[static_cast<std::size_t>(z * kSide + x)] >= threshold ? 255 : 0;
    }
  return map;
}

}  // namespace terrasol::packgen
