#include "light/sky_columns.h"

#include <algorithm>

namespace terrasol::light {

void computeSkyTops(const Chunk& chunk, const std::uint8_t* stops, ChunkLight& light) {
  light.skyTop.fill(static_cast<std::int16_t>(kMinY - 1));
  std::array<bool, kChunkArea> done{};
  int remaining = kChunkArea;
  for (int s = kSectionCount - 1; s >= 0 && remaining > 0; --s) {
    const Section& section = chunk.section(s);
    if (section.isUniform()) {
      const std::uint8_t stop = stops[section.uniformBlock()];
      if (stop == 0) continue;
      for (std::size_t i = 0; i < kChunkArea; ++i) {
        if (!done[i])
          light.skyTop[i] = static_cast<std::int16_t>(skyTopUnder(stop, sectionMinY(s) + kLastCell));
      }
      break;
    }
    for (int ly = kLastCell; ly >= 0; --ly)
      for (std::size_t i = 0; i < kChunkArea; ++i) {
        const std::uint8_t stop = stops[section.at(ly * kChunkArea + static_cast<int>(i))];
        if (done[i] || stop == 0) continue;
        done[i] = true;
        light.skyTop[i] = static_cast<std::int16_t>(skyTopUnder(stop, sectionMinY(s) + ly));
        --remaining;
      }
  }
}

void fillOpenSky(ChunkLight& light) {
  const auto [lowest, highest] = std::minmax_element(light.skyTop.begin(), light.skyTop.end());
  for (int s = 0; s < kSectionCount; ++s) {
    const int bottom = sectionMinY(s);
    NibbleArray& sky = light.sky[static_cast<std::size_t>(s)];
    sky.fill(bottom > *highest ? kMaxLight : 0);
    if (bottom > *highest || bottom + kLastCell <= *lowest) continue;
    for (int ly = 0; ly < kChunkSize; ++ly)
      for (std::size_t i = 0; i < kChunkArea; ++i) {
        if (bottom + ly > light.skyTop[i]) sky.set(ly * kChunkArea + static_cast<int>(i), kMaxLight);
      }
  }
}

std::array<int, kChunkArea> spreadTops(const World& world, const Chunk& chunk) {
  const ChunkPos pos = chunk.pos();
  const Chunk* around[4];
  for (int k = 0; k < 4; ++k) {
    const BlockPos& o = kDirectionOffsets[kHorizontal[k]];
    const Chunk* c = world.chunk({pos.x + o.x, pos.z + o.z});
    around[k] = c && c->light().lit ? c : nullptr;
  }
  std::array<int, kChunkArea> tops;
  for (int lz = 0; lz < kChunkSize; ++lz)
    for (int lx = 0; lx < kChunkSize; ++lx) {
      int highest = chunk.light().skyTop[static_cast<std::size_t>(columnIndex(lx, lz))] + 1;
      for (int k = 0; k < 4; ++k) {
        const BlockPos& o = kDirectionOffsets[kHorizontal[k]];
        const int nx = lx + o.x, nz = lz + o.z;
        const bool outside = nx < 0 || nx > kLastCell || nz < 0 || nz > kLastCell;
        const Chunk* c = outside ? around[k] : &chunk;
        if (c)
          highest = std::max<int>(
              highest, c->light().skyTop[static_cast<std::size_t>(columnIndex(localOf(nx), localOf(nz)))]);
      }
      tops[static_cast<std::size_t>(columnIndex(lx, lz))] = highest;
    }
  return tops;
}

}  // namespace terrasol::light
