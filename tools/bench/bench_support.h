#pragma once
// Shared set-up for the benchmarks: the default block table and a lit square of generated chunks.

#include <memory>
#include <string>

#include "core/paths.h"
#include "light/light_engine.h"
#include "world/generator.h"

namespace terrasol::bench {

inline const BlockRegistry& blocks() {
  static const BlockRegistry registry = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  return registry;
}

// Chunks -radius..radius around the origin from `generator` (seed 1), lit.
struct LitArea {
  LitArea(const std::string& generator, int radius, const BlockShapes* shapes = nullptr)
      : world(blocks(), shapes), light(world) {
    gen = makeGenerator({generator, 1, {}}, blocks());
    for (int z = -radius; z <= radius; ++z)
      for (int x = -radius; x <= radius; ++x) {
        auto c = std::make_unique<Chunk>(ChunkPos{x, z});
        gen->generate(*c);
        world.insertChunk(std::move(c));
        light.chunkLoaded({x, z});
      }
  }
  void set(const BlockPos& p, BlockId id) {
    if (const auto change = world.setBlock(p, id)) light.blockChanged(*change);
  }

  World world;
  LightEngine light;
  std::unique_ptr<ChunkGenerator> gen;
};

}  // namespace terrasol::bench
