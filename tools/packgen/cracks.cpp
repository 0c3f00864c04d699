// The default pack's crack over a block being dug (textures/block/destroy_stage_0..9.png): a crack
// grown from the middle out in branching walks, each stage showing the next tenth of it and keeping
// the last stage's. Dark texels where the stone splits, a light rim below and right of them where its
// edge catches the light, the rest transparent; the renderer multiplies 2 x texel into the block, so
// dark darkens and light brightens, as Minecraft's do.

#include <array>
#include <random>
#include <vector>

#include "assets/crack_textures.h"
#include "packgen.h"

namespace terrasol::packgen {
namespace {

constexpr int kSide = 16;
constexpr int kCrackTexels = 96;  // of the 256: the last stage is cracked all over
constexpr std::uint8_t kDark = 56, kLight = 144;
constexpr std::uint32_t kSeed = 1911;

struct Tip {
  int x, y, direction;  // one of the eight neighbours, 0 = east, counted clockwise
};
constexpr std::array<std::array<int, 2>, 8> kSteps{
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

// The order each texel cracks in (-1: never), grown by walks that turn a little and now and then fork.
std::vector<int> crackOrder() {
  std::mt19937 random(kSeed);
  std::vector<int> order(kSide * kSide, -1);
  std::vector<Tip> tips;
  for (int d = 0; d < 8; d += 3) tips.push_back({kSide / 2, kSide / 2, d});
  int cracked = 0;
  for (int step = 0; cracked < kCrackTexels && !tips.empty() && step < 4096; ++step) {
    Tip& tip = tips[static_cast<std::size_t>(step) % tips.size()];
    const std::uint32_t r = random();
    if (r % 4 == 0) tip.direction = (tip.direction + (r % 8 < 4 ? 1 : 7)) % 8;
    tip.x += kSteps[static_cast<std::size_t>(tip.direction)][0];
    tip.y += kSteps[static_cast<std::size_t>(tip.direction)][1];
    if (tip.x < 0 || tip.y < 0 || tip.x >= kSide || tip.y >= kSide) {  // a new walk from the middle
      tip = {kSide / 2, kSide / 2, static_cast<int>(r % 8)};
      continue;
    }
    int& at = order[static_cast<std::size_t>(tip.y * kSide + tip.x)];
    if (at < 0) at = cracked++;
    if (r % 11 == 0 && tips.size() < 8) tips.push_back({tip.x, tip.y, (tip.direction + 2) % 8});
  }
  return order;
}

}  // namespace

std::vector<Image> generateCracks() {
  const std::vector<int> order = crackOrder();
  std::vector<Image> stages;
  for (int stage = 0; stage < kCrackStages; ++stage) {
    const int shown = kCrackTexels * (stage + 1) / kCrackStages;
    const auto dark = [&](int x, int y) {
      const int o = order[static_cast<std::size_t>(y * kSide + x)];
      return o >= 0 && o < shown;
    };
    Image image(kSide, kSide);
    for (int y = 0; y < kSide; ++y) {
      for (int x = 0; x < kSide; ++x) {
        std::uint8_t* p = image.pixel(x, y);
        const bool rim = !dark(x, y) && x > 0 && y > 0 && dark(x - 1, y - 1);
        if (!dark(x, y) && !rim) continue;
        const std::uint8_t v = rim ? kLight : kDark;
        p[0] = p[1] = p[2] = v;
        p[3] = 255;
      }
    }
    stages.push_back(std::move(image));
  }
  return stages;
}

}  // namespace terrasol::packgen
