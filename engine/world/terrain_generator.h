#pragma once
// The `terrain` generator: seeded, deterministic Minecraft-like land. Shape from 2D noise (continents,
// hills, ridged mountains), sea-level water, beaches, snowy peaks; biomes (world/biomes.h) decide
// the ground (grass, desert sand over sandstone, snow-covered grass and ice), the trees (oak, birch,
// spruce, acacia, cacti) and the plants; deepslate below y = 0 (blending into stone up to y = 7); 3D
// noise caves (tunnels and caverns, open to the surface on land), lava below y = -54; ores by depth
// (in deepslate, their deepslate forms), glowstone clusters on deep cave ceilings.

#include <array>
#include <cstdint>

#include "world/biomes.h"
#include "world/generator.h"
#include "world/noise.h"

namespace terrasol {

class TerrainGenerator final : public ChunkGenerator {
 public:
  static constexpr int kSeaLevel = 62;  // highest water block
  static constexpr int kLavaLevel = -54;  // caves at or below fill with lava
  static constexpr int kDeepslateTop = 8;  // stone from here up; below y = 0 deepslate; a blend between

  TerrainGenerator(std::uint64_t seed, const BlockRegistry& blocks);

  void generate(Chunk& chunk) const override;
  int surfaceHeight(int x, int z) const override;
  void fillTints(Chunk& chunk) const override;

  // Cave density at a block: negative inside a cave. Pure; the same value generate() uses.
  double caveDensity(int x, int y, int z) const;
  // The biome of a column.
  Biome biomeAt(int x, int z) const { return biomes_.biomeAt(x, z, surfaceHeight(x, z)); }
  const BiomeSource& biomes() const { return biomes_; }

  struct Blocks {
    BlockId stone, dirt, grass, sand, gravel, bedrock, water, lava, snow, log, leaves, shortGrass, dandelion,
        poppy, coalOre, ironOre, goldOre, glowstone, deepslate, deepslateCoalOre, deepslateIronOre,
        deepslateGoldOre, copperOre, deepslateCopperOre, lapisOre, deepslateLapisOre, diamondOre,
        deepslateDiamondOre, emeraldOre, sandstone, ice, snowLayer, birchLog, birchLeaves, spruceLog, spruceLeaves,
        acaciaLog, acaciaLeaves, cactus, deadBush, fern;
  };

 private:
  // Cave density is evaluated on a lattice of 4 x 8 x 4 blocks and interpolated in between.
  static constexpr int kCaveCellXZ = 4;
  static constexpr int kCaveCellY = 8;

  double caveLattice(std::int64_t cx, std::int64_t cy, std::int64_t cz) const;
  bool carveAllowed(int y, int surface) const;

  void placeOres(Chunk& chunk) const;
  void placeGlowstone(Chunk& chunk) const;
  void placeTrees(Chunk& chunk) const;
  void placeTree(Chunk& chunk, Biome biome, int tx, int ground, int tz, std::uint64_t h) const;
  void placePlants(Chunk& chunk) const;

  std::uint64_t seed_;
  Blocks b_;
  BiomeSource biomes_;
  Noise continents_, hills_, mountains_, ridges_, tunnelA_, tunnelB_, caverns_, forests_;
};

}  // namespace terrasol
