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

}  // namespace terrasol
