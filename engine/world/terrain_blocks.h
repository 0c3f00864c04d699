#pragma once
// The blocks the terrain generator places, looked up by name once.

#include "world/block_registry.h"

namespace terrasol {

struct TerrainBlocks {
  explicit TerrainBlocks(const BlockRegistry& registry);

  BlockId stone, dirt, grass, sand, gravel, bedrock, water, lava, snow, log, leaves, shortGrass, dandelion,
      poppy, coalOre, ironOre, goldOre, glowstone, deepslate, deepslateCoalOre, deepslateIronOre,
      deepslateGoldOre, copperOre, deepslateCopperOre, lapisOre, deepslateLapisOre, diamondOre,
      deepslateDiamondOre, emeraldOre, sandstone, ice, snowLayer, birchLog, birchLeaves, spruceLog,
      spruceLeaves, acaciaLog, acaciaLeaves, cactus, deadBush, fern;
};

}  // namespace terrasol
