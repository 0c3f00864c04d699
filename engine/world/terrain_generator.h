#pragma once
// The `terrain` generator: seeded, deterministic Minecraft-like land. Shape from 2D noise (continents,
// hills, ridged mountains), sea-level water, beaches, snowy peaks; biomes (world/biomes.h) decide
// the ground (grass, desert sand over sandstone, snow-covered grass and ice), the trees (oak, birch,
// spruce, acacia, cacti) and the plants; deepslate below y = 0 (blending into stone up to y = 7); 3D
// noise caves (tunnels and caverns, open to the surface on land), lava below y = -54; ores by depth
// (in deepslate, their deepslate forms), glowstone clusters on deep cave ceilings.

#include <cstdint>

#include "world/biomes.h"
#include "world/generator.h"
#include "world/terrain_blocks.h"
#include "world/terrain_caves.h"
#include "world/terrain_shape.h"
#include "world/terrain_stages.h"
#include "world/terrain_trees.h"

namespace terrasol {

// Runs the stages of world/terrain_*.h in order; holds what they share.
class TerrainGenerator final : public ChunkGenerator {
 public:
  static constexpr int kSeaLevel = TerrainShape::kSeaLevel;
  static constexpr int kLavaLevel = TerrainCaves::kLavaLevel;
  static constexpr int kDeepslateTop = terrasol::kDeepslateTop;

  TerrainGenerator(std::uint64_t seed, const BlockRegistry& blocks);

  void generate(Chunk& chunk) const override;
  int surfaceHeight(int x, int z) const override { return shape_.surfaceHeight(x, z); }
  void fillTints(Chunk& chunk) const override { blendTints(chunk, context()); }

  // Cave density at a block: negative inside a cave. Pure; the same value generate() uses.
  double caveDensity(int x, int y, int z) const { return caves_.density(x, y, z); }
  // The biome of a column.
  Biome biomeAt(int x, int z) const { return context().biomeAt(x, z); }
  // A column's ground and water, from the same rules generate() uses.
  std::optional<SurfaceColumn> surfaceColumn(int x, int z) const override;
  void treeCrowns(ChunkPos at, std::vector<TreeCrown>& out) const override {
    trees_.crowns(at, context(), out);
  }
  const BiomeSource& biomes() const { return biomes_; }

 private:
  TerrainContext context() const { return {seed_, blocks_, shape_, caves_, biomes_}; }

  std::uint64_t seed_;
  TerrainBlocks blocks_;
  BiomeSource biomes_;
  TerrainShape shape_;
  TerrainCaves caves_;
  TerrainTrees trees_;
};

}  // namespace terrasol
