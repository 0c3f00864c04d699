#include "world/terrain_generator.h"

namespace terrasol {

TerrainGenerator::TerrainGenerator(std::uint64_t seed, const BlockRegistry& r)
    : seed_(seed), blocks_(r), biomes_(seed), shape_(seed), caves_(seed), trees_(seed) {}

void TerrainGenerator::generate(Chunk& chunk) const {
  const TerrainContext t = context();
  const ColumnSamples columns = sampleColumns(chunk.pos(), t);
  ColumnBlocks blocks;
  fillGround(blocks, columns, chunk.pos(), t);
  caves_.carve(blocks, columns, chunk.pos(), blocks_);
  coverSnow(blocks, columns, t);
  blocks.copyTo(chunk);

  placeOres(chunk, t);
  placeGlowstone(chunk, t);
  trees_.place(chunk, t);
  placePlants(chunk, t);
  blendTints(chunk, t);
  chunk.compact();
}

std::optional<SurfaceColumn> TerrainGenerator::surfaceColumn(int x, int z) const {
  const int h = shape_.surfaceHeight(x, z);
  const Biome biome = biomes_.biomeAt(x, z, h);
  SurfaceColumn c{h, surfaceBlockOf(h, biome, hashCoords(seed_, x, 1, z), blocks_)};
  c.climate = biomeTint(biome);
  if (h < kSeaLevel) {
    c.water = kSeaLevel;
    c.waterBlock = biome == Biome::SnowyPlains ? blocks_.ice : blocks_.water;
  }
  return c;
}

}  // namespace terrasol
