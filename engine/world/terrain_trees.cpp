#include "world/terrain_trees.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace terrasol {
namespace {

bool insideChunk(const Chunk& chunk, int wx, int wz) {
  return chunkOf(wx) == chunk.pos().x && chunkOf(wz) == chunk.pos().z;
}

BlockId getWorld(const Chunk& chunk, int wx, int y, int wz) {
  return chunk.get(localOf(wx), y, localOf(wz));
}
void setWorld(Chunk& chunk, int wx, int y, int wz, BlockId id) {
  chunk.set(localOf(wx), y, localOf(wz), id);
}

// A tree's kind and size, of its biome: oak (now and then a birch in a forest), birch, spruce in the
// taiga and the snow, acacia on the savanna; none in the desert (trunk 0).
struct TreeShape {
  BlockId log, leaves;
  int trunk = 0;
  bool spruce = false, flat = false;
};

TreeShape treeShapeOf(const TerrainBlocks& b, Biome biome, std::uint64_t h) {
  TreeShape s{b.log, b.leaves, 4 + static_cast<int>((h >> 8) % 3)};
  if (biome == Biome::BirchForest || (biome == Biome::Forest && (h >> 56) % 5 == 0)) {
    s.log = b.birchLog, s.leaves = b.birchLeaves, s.trunk += 1;
  } else if (biome == Biome::Taiga || biome == Biome::SnowyPlains) {
    s.log = b.spruceLog, s.leaves = b.spruceLeaves, s.spruce = true, s.trunk += 3;
  } else if (biome == Biome::Savanna) {
    s.log = b.acaciaLog, s.leaves = b.acaciaLeaves, s.flat = true;
  } else if (biome == Biome::Desert) {
    s.trunk = 0;
  }
  return s;
}

// One tree rooted at (tx, ground, tz). Each chunk writes its own blocks.
void placeTree(Chunk& chunk, const TerrainBlocks& b, Biome biome, int tx, int ground, int tz,
               std::uint64_t h) {
  const TreeShape shape = treeShapeOf(b, biome, h);
  if (shape.trunk == 0) return;
  const BlockId log = shape.log, leaves = shape.leaves;
  const bool spruce = shape.spruce, flat = shape.flat;
  const int top = ground + shape.trunk;
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
    setWorld(chunk, tx, ground, tz, b.dirt);
    for (int y = ground + 1; y < top + (spruce ? 1 : 0); ++y) setWorld(chunk, tx, y, tz, log);
  }
}

}  // namespace

template <class F>
void TerrainTrees::forEachTree(ChunkPos at, const TerrainContext& t, F&& f) const {
  // Forest density varies smoothly: none on open plains, up to 8 trees per chunk in woods; forest
  // biomes are wooded throughout, savannas have lone trees, deserts none.
  const Biome area = t.biomeAt(at.x * kChunkSize + kChunkSize / 2, at.z * kChunkSize + kChunkSize / 2);
  const double forest = forests_.fractal(at.x / 12.0, at.z / 12.0, 2) * 2.0;
  int attempts = forest > 0.1 ? static_cast<int>(std::min(8.0, 2.0 + forest * 10.0)) : 1;
  if (area == Biome::Forest || area == Biome::BirchForest || area == Biome::Taiga)
    attempts = std::max(attempts, 4);
  if (area == Biome::Savanna) attempts = 1;
  if (area == Biome::Desert) attempts = 0;
  for (int i = 0; i < attempts; ++i) {
    const std::uint64_t h = hashCoords(t.seed ^ kTreeSalt, at.x, i, at.z);
    if (attempts == 1 && (h >> 60) > 3) continue;  // lone trees: 1 chunk in 4
    const int tx = at.x * kChunkSize + static_cast<int>(h & kLastCell),
              tz = at.z * kChunkSize + static_cast<int>((h >> kChunkShift) & kLastCell);
    const int ground = t.shape.surfaceHeight(tx, tz);
    if (ground <= TerrainShape::kSeaLevel + 1 || ground >= TerrainShape::kRockyFrom)
      continue;  // not on beaches, sea beds or rock
    if (t.caves.density(tx, ground, tz) < 0.0 && TerrainCaves::carveAllowed(ground, ground))
      continue;  // ground carved away
    f(tx, ground, tz, h, t.biomes.biomeAt(tx, tz, ground));
  }
}

void TerrainTrees::place(Chunk& chunk, const TerrainContext& t) const {
  const ChunkPos p = chunk.pos();
  for (int ncz = p.z - 1; ncz <= p.z + 1; ++ncz)
    for (int ncx = p.x - 1; ncx <= p.x + 1; ++ncx) {
      forEachTree({ncx, ncz}, t, [&](int tx, int ground, int tz, std::uint64_t h, Biome biome) {
        placeTree(chunk, t.blocks, biome, tx, ground, tz, h);
      });
    }
}

void TerrainTrees::crowns(ChunkPos at, const TerrainContext& t, std::vector<TreeCrown>& out) const {
  forEachTree(at, t, [&](int tx, int ground, int tz, std::uint64_t h, Biome biome) {
    const TreeShape s = treeShapeOf(t.blocks, biome, h);
    if (s.trunk == 0) return;
    // As placeTree grows them: an oak's two wide layers under its narrow top, a spruce's cone (radius
    // 2 three below its top), an acacia's flat layer with a narrow one on it.
    const int top = ground + s.trunk;
    if (s.spruce) {
      out.push_back({tx, tz, 1, top, 2, top - 3, s.leaves});  // its one-column tip left out
    } else {
      out.push_back({tx, tz, 1, top + 1, s.flat ? 3 : 2, s.flat ? top : top - 1, s.leaves});
    }
  });
}

}  // namespace terrasol
