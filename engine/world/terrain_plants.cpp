// The terrain generator's last block stage: plants on the surface.
#include "world/terrain_stages.h"

namespace terrasol {

void placePlants(Chunk& chunk, const TerrainContext& t) {
  const TerrainBlocks& b = t.blocks;
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      const int y = t.shape.surfaceHeight(x0 + x, z0 + z);
      const BlockId ground = chunk.get(x, y, z);
      if ((ground != b.grass && ground != b.sand) || chunk.get(x, y + 1, z) != kAir) continue;
      const std::uint64_t hash = hashCoords(t.seed ^ kPlantSalt, x0 + x, y, z0 + z), roll = hash % 1000;
      const Biome biome = t.biomes.biomeAt(x0 + x, z0 + z, y);
      if (biome == Biome::Desert) {
        if (ground != b.sand) continue;
        if (roll < 8) chunk.set(x, y + 1, z, b.deadBush);
        // Cacti, one to three high, with nothing beside them.
        if (roll >= 990 && x > 0 && x < kLastCell && z > 0 && z < kLastCell &&
            chunk.get(x - 1, y + 1, z) == kAir && chunk.get(x + 1, y + 1, z) == kAir &&
            chunk.get(x, y + 1, z - 1) == kAir && chunk.get(x, y + 1, z + 1) == kAir) {
          for (int k = 1; k <= 1 + static_cast<int>(roll % 3); ++k) chunk.set(x, y + k, z, b.cactus);
        }
        continue;
      }
      if (ground != b.grass) continue;
      BlockId plant = kAir;
      if (biome == Biome::Taiga) {
        plant = roll < 100 ? b.fern : roll < 160 ? b.shortGrass : kAir;
      } else if (biome == Biome::Savanna) {
        plant = roll < 250 ? b.shortGrass : kAir;
      } else {
        const std::uint64_t percent = hash % 100;
        plant = percent < 14 ? b.shortGrass : percent < 15 ? b.dandelion : percent < 16 ? b.poppy : kAir;
      }
      if (plant != kAir) chunk.set(x, y + 1, z, plant);
    }
}

}  // namespace terrasol
