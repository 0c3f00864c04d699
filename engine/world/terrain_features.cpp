// Features the terrain generator adds after shaping and carving. Each feature is placed from hashes
// of the seed and the chunk it starts in; features that reach across a border (trees) are replayed
// by every chunk they touch, each writing only its own blocks, so the result is independent of
// generation order.

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "world/terrain_generator.h"

namespace terrasol {
namespace {

// Feature kinds, mixed into hashes so each draws its own random numbers.
enum Salt : std::int64_t { kOreSalt = 101, kGlowSalt = 102, kTreeSalt = 103, kPlantSalt = 104 };

bool insideChunk(const Chunk& chunk, int wx, int wz) {
  return chunkOf(wx) == chunk.pos().x && chunkOf(wz) == chunk.pos().z;
}

BlockId getWorld(const Chunk& chunk, int wx, int y, int wz) {
  return chunk.get(localOf(wx), y, localOf(wz));
}
void setWorld(Chunk& chunk, int wx, int y, int wz, BlockId id) {
  chunk.set(localOf(wx), y, localOf(wz), id);
}

struct OreKind {
  BlockId TerrainGenerator::Blocks::*block;
  BlockId TerrainGenerator::Blocks::*deep;  // in deepslate
  int attempts;                             // veins started per chunk
  int minY, maxY;
  double radius;
};

}  // namespace

void TerrainGenerator::placeOres(Chunk& chunk) const {
  // Depths as Minecraft spreads them, roughly: coal high, iron and copper in the middle, gold, lapis
  // and diamonds deep (diamonds only below y = 16), emeralds high in the mountains.
  static constexpr OreKind kOres[] = {
      {&Blocks::coalOre, &Blocks::deepslateCoalOre, 14, 0, 130, 1.6},
      {&Blocks::ironOre, &Blocks::deepslateIronOre, 10, -60, 72, 1.3},
      {&Blocks::goldOre, &Blocks::deepslateGoldOre, 3, -60, 30, 1.1},
      {&Blocks::copperOre, &Blocks::deepslateCopperOre, 6, -16, 112, 1.5},
      {&Blocks::lapisOre, &Blocks::deepslateLapisOre, 2, -60, 64, 1.1},
      {&Blocks::diamondOre, &Blocks::deepslateDiamondOre, 2, -60, 16, 1.0},
      {&Blocks::emeraldOre, &Blocks::emeraldOre, 3, 100, 230, 0.6},
  };
  const ChunkPos p = chunk.pos();
  for (std::size_t kind = 0; kind < std::size(kOres); ++kind) {
    const OreKind& ore = kOres[kind];
    for (int i = 0; i < ore.attempts; ++i) {
      const std::uint64_t h = hashCoords(seed_ ^ (kOreSalt + kind), p.x, i, p.z);
      const int cx = static_cast<int>(h & 15), cz = static_cast<int>((h >> 4) & 15);
      const int cy = ore.minY + static_cast<int>((h >> 8) % static_cast<std::uint64_t>(ore.maxY - ore.minY));
      const int r = static_cast<int>(std::ceil(ore.radius));
      for (int dy = -r; dy <= r; ++dy)
        for (int dz = -r; dz <= r; ++dz)
          for (int dx = -r; dx <= r; ++dx) {
            const int x = cx + dx, y = cy + dy, z = cz + dz;
            if (x < 0 || x > 15 || z < 0 || z > 15 || dx * dx + dy * dy + dz * dz > ore.radius * ore.radius)
              continue;
            // Ragged edges: each cell of the sphere is kept with probability 3/4.
            if ((hashCoords(h, dx, dy, dz) & 3) == 0) continue;
            const BlockId here = chunk.get(x, y, z);
            if (here == b_.stone) chunk.set(x, y, z, b_.*ore.block);
            if (here == b_.deepslate) chunk.set(x, y, z, b_.*ore.deep);
          }
    }
  }
}

void TerrainGenerator::placeGlowstone(Chunk& chunk) const {
  const ChunkPos p = chunk.pos();
  for (int i = 0; i < 8; ++i) {
    const std::uint64_t h = hashCoords(seed_ ^ kGlowSalt, p.x, i, p.z);
    const int x = static_cast<int>(h & 15), z = static_cast<int>((h >> 4) & 15);
    const int start = -56 + static_cast<int>((h >> 8) % 50);  // deep caves, y -56..-7
    // Find a cave ceiling above the start: air with stone over it.
    int ceiling = kMinY - 1;
    for (int y = start; y < start + 16; ++y) {
      const BlockId above = chunk.get(x, y + 1, z);
      if (chunk.get(x, y, z) == kAir && (above == b_.stone || above == b_.deepslate)) {
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
          if (bx < 0 || bx > 15 || bz < 0 || bz > 15) continue;
          const int reach = 2 + dy;  // narrower the lower it hangs
          if (dx * dx + dz * dz > reach * reach + 1 || (hashCoords(h, dx, dy, dz) & 3) == 0) continue;
          const BlockId here = chunk.get(bx, by, bz);
          const bool rock = here == b_.stone || here == b_.deepslate;
          if ((dy == 0 && rock) || (dy < 0 && here == kAir)) chunk.set(bx, by, bz, b_.glowstone);
        }
  }
}

void TerrainGenerator::placeTrees(Chunk& chunk) const {
  const ChunkPos p = chunk.pos();
  for (int ncz = p.z - 1; ncz <= p.z + 1; ++ncz)
    for (int ncx = p.x - 1; ncx <= p.x + 1; ++ncx) {
      // Forest density varies smoothly: none on open plains, up to 8 trees per chunk in woods; forest
      // biomes are wooded throughout, savannas have lone trees, deserts none.
      const Biome area = biomeAt(ncx * 16 + 8, ncz * 16 + 8);
      const double forest = forests_.fractal(ncx / 12.0, ncz / 12.0, 2) * 2.0;
      int attempts = forest > 0.1 ? static_cast<int>(std::min(8.0, 2.0 + forest * 10.0)) : 1;
      if (area == Biome::Forest || area == Biome::BirchForest || area == Biome::Taiga)
        attempts = std::max(attempts, 4);
      if (area == Biome::Savanna) attempts = 1;
      if (area == Biome::Desert) attempts = 0;
      for (int i = 0; i < attempts; ++i) {
        const std::uint64_t h = hashCoords(seed_ ^ kTreeSalt, ncx, i, ncz);
        if (attempts == 1 && (h >> 60) > 3) continue;  // lone trees: 1 chunk in 4
        const int tx = ncx * 16 + static_cast<int>(h & 15), tz = ncz * 16 + static_cast<int>((h >> 4) & 15);
        const int ground = surfaceHeight(tx, tz);
        if (ground <= kSeaLevel + 1 || ground >= 118) continue;  // not on beaches, sea beds or rock
        if (caveDensity(tx, ground, tz) < 0.0 && carveAllowed(ground, ground))
          continue;  // ground carved away
        placeTree(chunk, biomes_.biomeAt(tx, tz, ground), tx, ground, tz, h);
      }
    }
}

// One tree rooted at (tx, ground, tz), of its biome's kind: oak (now and then a birch in a forest),
// birch, spruce in the taiga and the snow, acacia on the savanna. Each chunk writes its own blocks.
void TerrainGenerator::placeTree(Chunk& chunk, Biome biome, int tx, int ground, int tz,
                                 std::uint64_t h) const {
  BlockId log = b_.log, leaves = b_.leaves;
  bool spruce = false, flat = false;
  int trunk = 4 + static_cast<int>((h >> 8) % 3);
  if (biome == Biome::BirchForest || (biome == Biome::Forest && (h >> 56) % 5 == 0)) {
    log = b_.birchLog, leaves = b_.birchLeaves, trunk += 1;
  } else if (biome == Biome::Taiga || biome == Biome::SnowyPlains) {
    log = b_.spruceLog, leaves = b_.spruceLeaves, spruce = true, trunk += 3;
  } else if (biome == Biome::Savanna) {
    log = b_.acaciaLog, leaves = b_.acaciaLeaves, flat = true;
  } else if (biome == Biome::Desert) {
    return;
  }
  const int top = ground + trunk;
  const auto leaf = [&](int lx, int y, int lz) {
    if (insideChunk(chunk, lx, lz) && getWorld(chunk, lx, y, lz) == kAir) setWorld(chunk, lx, y, lz, leaves);
  };
  if (spruce) {
    // A cone: a tip above the top, then rings widening and narrowing down to three above the ground.
    leaf(tx, top + 1, tz);
    for (int y = top; y >= ground + 3; --y) {
      const int radius = (top - y) % 2 == 0 ? 1 : std::min(3, 1 + (top - y) / 3);
      for (int dz = -radius; dz <= radius; ++dz)
        for (int dx = -radius; dx <= radius; ++dx) {
          if (std::abs(dx) + std::abs(dz) > radius + (radius > 1 ? 1 : 0)) continue;
          leaf(tx + dx, y, tz + dz);
        }
    }
  } else {
    // Leaves: two wide layers below the top, two narrow ones at and above it; an acacia's are one
    // wide flat layer with a narrow one on it.
    for (int y = flat ? top : top - 2; y <= top + 1; ++y) {
      const int radius = y < top || (flat && y == top) ? (flat ? 3 : 2) : 1;
      for (int dz = -radius; dz <= radius; ++dz)
        for (int dx = -radius; dx <= radius; ++dx) {
          const bool corner = std::abs(dx) == radius && std::abs(dz) == radius;
          if (corner && (radius == 1 ? y == top + 1 : (hashCoords(h, dx, y, dz) & 1))) continue;
          leaf(tx + dx, y, tz + dz);
        }
    }
  }
  if (insideChunk(chunk, tx, tz)) {
    setWorld(chunk, tx, ground, tz, b_.dirt);
    for (int y = ground + 1; y < top + (spruce ? 1 : 0); ++y) setWorld(chunk, tx, y, tz, log);
  }
}

void TerrainGenerator::placePlants(Chunk& chunk) const {
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) {
      const int y = surfaceHeight(x0 + x, z0 + z);
      const BlockId ground = chunk.get(x, y, z);
      if ((ground != b_.grass && ground != b_.sand) || chunk.get(x, y + 1, z) != kAir) continue;
      const std::uint64_t hash = hashCoords(seed_ ^ kPlantSalt, x0 + x, y, z0 + z), roll = hash % 1000;
      const Biome biome = biomes_.biomeAt(x0 + x, z0 + z, y);
      if (biome == Biome::Desert) {
        if (ground != b_.sand) continue;
        if (roll < 8) chunk.set(x, y + 1, z, b_.deadBush);
        // Cacti, one to three high, with nothing beside them.
        if (roll >= 990 && x > 0 && x < 15 && z > 0 && z < 15 && chunk.get(x - 1, y + 1, z) == kAir &&
            chunk.get(x + 1, y + 1, z) == kAir && chunk.get(x, y + 1, z - 1) == kAir &&
            chunk.get(x, y + 1, z + 1) == kAir) {
          for (int k = 1; k <= 1 + static_cast<int>(roll % 3); ++k) chunk.set(x, y + k, z, b_.cactus);
        }
        continue;
      }
      if (ground != b_.grass) continue;
      BlockId plant = kAir;
      if (biome == Biome::Taiga) {
        plant = roll < 100 ? b_.fern : roll < 160 ? b_.shortGrass : kAir;
      } else if (biome == Biome::Savanna) {
        plant = roll < 250 ? b_.shortGrass : kAir;
      } else {
        const std::uint64_t percent = hash % 100;
        plant = percent < 14 ? b_.shortGrass : percent < 15 ? b_.dandelion : percent < 16 ? b_.poppy : kAir;
      }
      if (plant != kAir) chunk.set(x, y + 1, z, plant);
    }
}

}  // namespace terrasol
