#pragma once
// The terrain generator's stages after the land's shape, each a pure function of the seed and the
// chunk's position, in the order TerrainGenerator::generate runs them. Features are placed from
// hashes of the seed and the chunk they start in; features that reach across a border (trees) are
// replayed by every chunk they touch, each writing only its own blocks, so the result is independent
// of generation order.

#include <cstdint>

#include "world/biomes.h"
#include "world/terrain_blocks.h"
#include "world/terrain_caves.h"
#include "world/terrain_columns.h"
#include "world/terrain_shape.h"

namespace terrasol {

// What the stages read: the seed, the blocks they place and the world's shape.
struct TerrainContext {
  std::uint64_t seed;
  const TerrainBlocks& blocks;
  const TerrainShape& shape;
  const TerrainCaves& caves;
  const BiomeSource& biomes;

  Biome biomeAt(int x, int z) const { return biomes.biomeAt(x, z, shape.surfaceHeight(x, z)); }
};

// Each column's surface height and biome.
ColumnSamples sampleColumns(ChunkPos pos, const TerrainContext& t);
// The block on top of a column of surface height `h` (before caves, snow and plants): snow on peaks,
// bare stone high up, sand or gravel under water, sand on beaches and in deserts, else grass. `r` is
// the column's hash (hashCoords(seed, x, 1, z)).
BlockId surfaceBlockOf(int h, Biome biome, std::uint64_t r, const TerrainBlocks& b);
inline constexpr int kDeepslateTop = 8;  // stone from here up; below y = 0 deepslate; a blend between
// Rock (deepslate below y = 0, blending into stone up to kDeepslateTop), bedrock, soil and sand,
// and water up to the sea level with ice on it in the snow.
void fillGround(ColumnBlocks& blocks, const ColumnSamples& columns, ChunkPos pos, const TerrainContext& t);
// A layer of snow on snowy ground that caves left in place.
void coverSnow(ColumnBlocks& blocks, const ColumnSamples& columns, const TerrainContext& t);

// Ore veins by depth (in deepslate, their deepslate forms).
void placeOres(Chunk& chunk, const TerrainContext& t);
// Glowstone clusters hanging from deep cave ceilings.
void placeGlowstone(Chunk& chunk, const TerrainContext& t);
// Flowers, grass, ferns, dead bushes and cacti on the surface, by biome.
void placePlants(Chunk& chunk, const TerrainContext& t);
// Each column's grass and foliage colour, blended across biome borders.
void blendTints(Chunk& chunk, const TerrainContext& terrain);

// Feature kinds, mixed into hashes so each draws its own random numbers.
enum TerrainSalt : std::int64_t { kOreSalt = 101, kGlowSalt = 102, kTreeSalt = 103, kPlantSalt = 104 };

}  // namespace terrasol
