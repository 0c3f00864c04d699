// The default pack's grass and foliage colormaps: smooth blends between three climates, as
// Minecraft's maps are. A texel (x, y) is temperature t = 1 - x / 255 and downfall-times-temperature
// d = 1 - y / 255; its colour weighs the cold corner by 1 - t, the hot dry one by t - d and the hot
// wet one by d (texels with d > t, which no biome reaches, take d = t). The corners are chosen so
// that the plains texel gives Minecraft's plains colours, #91BD59 and #77AB2F.

#include <algorithm>
#include <cmath>

#include "packgen.h"

namespace terrasol::packgen {
namespace {

struct Corners {
  glm::vec3 cold, hotDry, hotWet;  // sRGB 0..255
};

Image blend(const Corners& c) {
  Image map(256, 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const float t = 1.0f - static_cast<float>(x) / 255.0f;
      const float d = std::min(1.0f - static_cast<float>(y) / 255.0f, t);
      const glm::vec3 colour = c.cold * (1.0f - t) + c.hotDry * (t - d) + c.hotWet * d;
      std::uint8_t* p = map.pixel(x, y);
      for (int i = 0; i < 3; ++i)
        p[i] = static_cast<std::uint8_t>(std::clamp(std::lround(colour[i]), 0l, 255l));
      p[3] = 255;
    }
  return map;
}

}  // namespace

std::vector<GeneratedColormap> generateColormaps() {
  return {{"grass", blend({{128, 180, 151}, {191, 183, 85}, {87, 204, 56}})},
          {"foliage", blend({{96, 161, 123}, {174, 164, 42}, {51, 188, 7}})}};
}

}  // namespace terrasol::packgen
