#include "light/sky_columns.h"

#include <algorithm>

namespace terrasol::light {

void computeSkyTops(const Chunk& chunk, const std::uint8_t* stops, ChunkLight& light) {
  light.skyTop.fill(static_cast<std::int16_t>(kMinY - 1));
  std::array<bool, 256> done{};
  int remaining = 256;
  for (int s = kSectionCount - 1; s >= 0 && remaining > 0; --s) {
    const Section& section = chunk.section(s);
    if (section.isUniform()) {
      if (stops[section.uniformBlock()] == 0) continue;
      for (std::size_t i = 0; i < 256; ++i) {
        if (!done[i]) light.skyTop[i] = static_cast<std::int16_t>(kMinY + s * 16 + 15);
      }
      break;
    }
    for (int ly = 15; ly >= 0; --ly)
      for (std::size_t i = 0; i < 256; ++i) {
        if (done[i] || stops[section.at(ly * 256 + static_cast<int>(i))] == 0) continue;
        done[i] = true;
        light.skyTop[i] = static_cast<std::int16_t>(kMinY + s * 16 + ly);
        --remaining;
      }
  }
}

void fillOpenSky(ChunkLight& light) {
  const auto [lowest, highest] = std::minmax_element(light.skyTop.begin(), light.skyTop.end());
  for (int s = 0; s < kSectionCount; ++s) {
    const int bottom = kMinY + s * 16;
    NibbleArray& sky = light.sky[static_cast<std::size_t>(s)];
    sky.fill(bottom > *highest ? 15 : 0);
    if (bottom > *highest || bottom + 15 <= *lowest) continue;
    for (int ly = 0; ly < 16; ++ly)
      for (std::size_t i = 0; i < 256; ++i) {
        if (bottom + ly > light.skyTop[i]) sky.set(ly * 256 + static_cast<int>(i), 15);
      }
  }
}

std::array<int, 256> spreadTops(const World& world, const Chunk& chunk) {
  const ChunkPos pos = chunk.pos();
  const Chunk* around[4];
  for (int k = 0; k < 4; ++k) {
    const BlockPos& o = kDirectionOffsets[kHorizontal[k]];
    const Chunk* c = world.chunk({pos.x + o.x, pos.z + o.z});
    around[k] = c && c->light().lit ? c : nullptr;
  }
  std::array<int, 256> tops;
  for (int lz = 0; lz < 16; ++lz)
    for (int lx = 0; lx < 16; ++lx) {
      int highest = chunk.light().skyTop[static_cast<std::size_t>(lz * 16 + lx)] + 1;
      for (int k = 0; k < 4; ++k) {
        const BlockPos& o = kDirectionOffsets[kHorizontal[k]];
        const int nx = lx + o.x, nz = lz + o.z;
        const bool outside = nx < 0 || nx > 15 || nz < 0 || nz > 15;
        const Chunk* c = outside ? around[k] : &chunk;
        if (c)
          highest =
              std::max<int>(highest, c->light().skyTop[static_cast<std::size_t>((nz & 15) * 16 + (nx & 15))]);
      }
      tops[static_cast<std::size_t>(lz * 16 + lx)] = highest;
    }
  return tops;
}

}  // namespace terrasol::light
