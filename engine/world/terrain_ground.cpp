// The terrain generator's column stages: sampling, ground and snow.
#include "world/terrain_stages.h"

namespace terrasol {

ColumnSamples sampleColumns(ChunkPos pos, const TerrainContext& t) {
  const int x0 = pos.minBlockX(), z0 = pos.minBlockZ();
  ColumnSamples columns;
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      const int h = t.shape.surfaceHeight(x0 + x, z0 + z);
      columns[static_cast<std::size_t>(columnIndex(x, z))] = {h, t.biomes.biomeAt(x0 + x, z0 + z, h)};
    }
  return columns;
}

BlockId surfaceBlockOf(int h, Biome biome, std::uint64_t r, const TerrainBlocks& b) {
  constexpr int kSeaLevel = TerrainShape::kSeaLevel;
  const bool beach = h >= kSeaLevel - 3 && h <= kSeaLevel + 1;
  return h >= TerrainShape::kSnowyPeakFrom ? b.snow
         : h >= TerrainShape::kRockyFrom   ? b.stone
         : h < kSeaLevel - 3               ? ((r >> 40) % 4 == 0 ? b.gravel : b.sand)
         : beach || biome == Biome::Desert ? b.sand
                                           : b.grass;
}

void fillGround(ColumnBlocks& blocks, const ColumnSamples& columns, ChunkPos pos, const TerrainContext& t) {
  constexpr int kSeaLevel = TerrainShape::kSeaLevel;
  const TerrainBlocks& b = t.blocks;
  const int x0 = pos.minBlockX(), z0 = pos.minBlockZ();
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      const auto [h, biome] = columns[static_cast<std::size_t>(columnIndex(x, z))];
      const bool beach = h >= kSeaLevel - 3 && h <= kSeaLevel + 1;
      const bool underwater = h < kSeaLevel - 3;
      const bool rocky = h >= TerrainShape::kRockyFrom;
      const bool desert = biome == Biome::Desert, snowy = biome == Biome::SnowyPlains;
      const std::uint64_t r = hashCoords(t.seed, x0 + x, 1, z0 + z);
      const int depthOfDirt = 3 + static_cast<int>(r % 2);
      const int bedrockTop = kMinY + 1 + static_cast<int>((r >> 8) % 4);
      for (int y = kMinY; y <= h; ++y) {
        // Deepslate below y = 0, thinning out to none at kDeepslateTop.
        const bool deep =
            y < 0 || (y < kDeepslateTop &&
                      static_cast<int>(hashCoords(t.seed ^ 0x0D, x0 + x, y, z0 + z) % kDeepslateTop) >= y);
        BlockId id = deep ? b.deepslate : b.stone;
        if (y <= bedrockTop &&
            (y == kMinY || ((r >> (16 + y - kMinY)) & 1))) {  // r from bit 16: a bit a layer
          id = b.bedrock;
        } else if (y == h) {
          id = surfaceBlockOf(h, biome, r, b);
        } else if (y > h - depthOfDirt && !rocky) {
          id = (beach || underwater || desert) ? b.sand : b.dirt;
        } else if (desert && y > h - depthOfDirt - 4) {
          id = b.sandstone;  // sand lies on sandstone
        }
        blocks.at(x, y, z) = id;
      }
      for (int y = h + 1; y <= kSeaLevel; ++y) blocks.at(x, y, z) = b.water;
      // Snowy plains: ice on still water.
      if (snowy && h < kSeaLevel) blocks.at(x, kSeaLevel, z) = b.ice;
    }
}

void coverSnow(ColumnBlocks& blocks, const ColumnSamples& columns, const TerrainContext& t) {
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      const auto [h, biome] = columns[static_cast<std::size_t>(columnIndex(x, z))];
      const bool rocky = h >= TerrainShape::kRockyFrom;
      if (biome == Biome::SnowyPlains && h >= TerrainShape::kSeaLevel && !rocky &&
          blocks.at(x, h, z) != kAir) {
        blocks.at(x, h + 1, z) = t.blocks.snowLayer;
      }
    }
}

}  // namespace terrasol
