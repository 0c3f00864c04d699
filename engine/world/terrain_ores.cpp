// The terrain generator's stages underground: ore veins and glowstone.
#include <cmath>
#include <iterator>

#include "world/terrain_stages.h"

namespace terrasol {
namespace {

struct OreKind {
  BlockId TerrainBlocks::*block;
  BlockId TerrainBlocks::*deep;  // in deepslate
  int attempts;                  // veins started per chunk
  int minY, maxY;
  double radius;
};

// Whether a local x or z lies in the chunk.
bool isLocal(int v) {
  return v >= 0 && v <= kLastCell;
}

}  // namespace

void placeOres(Chunk& chunk, const TerrainContext& t) {
  // Depths as Minecraft spreads them, roughly: coal high, iron and copper in the middle, gold, lapis
  // and diamonds deep (diamonds only below y = 16), emeralds high in the mountains.
  static constexpr OreKind kOres[] = {
      {&TerrainBlocks::coalOre, &TerrainBlocks::deepslateCoalOre, 14, 0, 130, 1.6},
      {&TerrainBlocks::ironOre, &TerrainBlocks::deepslateIronOre, 10, -60, 72, 1.3},
      {&TerrainBlocks::goldOre, &TerrainBlocks::deepslateGoldOre, 3, -60, 30, 1.1},
      {&TerrainBlocks::copperOre, &TerrainBlocks::deepslateCopperOre, 6, -16, 112, 1.5},
      {&TerrainBlocks::lapisOre, &TerrainBlocks::deepslateLapisOre, 2, -60, 64, 1.1},
      {&TerrainBlocks::diamondOre, &TerrainBlocks::deepslateDiamondOre, 2, -60, 16, 1.0},
      {&TerrainBlocks::emeraldOre, &TerrainBlocks::emeraldOre, 3, 100, 230, 0.6},
  };
  const TerrainBlocks& b = t.blocks;
  const ChunkPos p = chunk.pos();
  for (std::size_t kind = 0; kind < std::size(kOres); ++kind) {
    const OreKind& ore = kOres[kind];
    for (int i = 0; i < ore.attempts; ++i) {
      const std::uint64_t h = hashCoords(t.seed ^ (kOreSalt + kind), p.x, i, p.z);
      const int cx = static_cast<int>(h & kLastCell), cz = static_cast<int>((h >> kChunkShift) & kLastCell);
      const int cy = ore.minY + static_cast<int>((h >> 8) % static_cast<std::uint64_t>(ore.maxY - ore.minY));
      const int r = static_cast<int>(std::ceil(ore.radius));
      for (int dy = -r; dy <= r; ++dy)
        for (int dz = -r; dz <= r; ++dz)
          for (int dx = -r; dx <= r; ++dx) {
            const int x = cx + dx, y = cy + dy, z = cz + dz;
            if (!isLocal(x) || !isLocal(z) || dx * dx + dy * dy + dz * dz > ore.radius * ore.radius) continue;
            // Ragged edges: each cell of the sphere is kept with probability 3/4.
            if ((hashCoords(h, dx, dy, dz) & 3) == 0) continue;
            const BlockId here = chunk.get(x, y, z);
            if (here == b.stone) chunk.set(x, y, z, b.*ore.block);
            if (here == b.deepslate) chunk.set(x, y, z, b.*ore.deep);
          }
    }
  }
}

void placeGlowstone(Chunk& chunk, const TerrainContext& t) {
  const TerrainBlocks& b = t.blocks;
  const ChunkPos p = chunk.pos();
  for (int i = 0; i < 8; ++i) {
    const std::uint64_t h = hashCoords(t.seed ^ kGlowSalt, p.x, i, p.z);
    const int x = static_cast<int>(h & kLastCell), z = static_cast<int>((h >> kChunkShift) & kLastCell);
    const int start = -56 + static_cast<int>((h >> 8) % 50);  // deep caves, y -56..-7
    // Find a cave ceiling up to 16 blocks above the start: air with stone over it.
    int ceiling = kMinY - 1;
    for (int y = start; y < start + 16; ++y) {
      const BlockId above = chunk.get(x, y + 1, z);
      if (chunk.get(x, y, z) == kAir && (above == b.stone || above == b.deepslate)) {
        ceiling = y + 1;
        break;
      }
    }
    if (ceiling < kMinY) continue;
    // A hanging cluster: the ceiling block becomes glowstone and blobs grow down into the air.
    for (int dy = 0; dy >= -3; --dy)
      for (int dz = -2; dz <= 2; ++dz)
        for (int dx = -2; dx <= 2; ++dx) {
          const int bx = x + dx, by = ceiling + dy, bz = z + dz;
          if (!isLocal(bx) || !isLocal(bz)) continue;
          const int reach = 2 + dy;  // narrower the lower it hangs
          if (dx * dx + dz * dz > reach * reach + 1 || (hashCoords(h, dx, dy, dz) & 3) == 0) continue;
          const BlockId here = chunk.get(bx, by, bz);
          const bool rock = here == b.stone || here == b.deepslate;
          if ((dy == 0 && rock) || (dy < 0 && here == kAir)) chunk.set(bx, by, bz, b.glowstone);
        }
  }
}

}  // namespace terrasol
