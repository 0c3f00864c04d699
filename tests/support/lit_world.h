#pragma once
// A lit world for the light tests: chunks from a generator, edits through the light engine, the
// default blocks shaped by hand (support/world_support.h's handShapes).

#include <memory>
#include <string>

#include "light/light_engine.h"
#include "support/world_support.h"
#include "world/generator.h"

namespace terrasol::testing {

// A world with light, loaded and edited the way the game does it.
struct LitWorld {
  explicit LitWorld(const std::string& generator, const std::string& layers = "")
      : world(defaultBlocks(), &handShapes()), light(world) {
    GeneratorSettings settings{generator, 1, {}};
    if (!layers.empty()) settings.flatLayers = parseFlatLayers(layers, defaultBlocks());
    gen = makeGenerator(settings, defaultBlocks());
  }
  void load(ChunkPos pos) {
    auto chunk = std::make_unique<Chunk>(pos);
    gen->generate(*chunk);
    world.insertChunk(std::move(chunk));
    light.chunkLoaded(pos);
  }
  void loadArea(int x0, int z0, int x1, int z1) {
    for (int z = z0; z <= z1; ++z)
      for (int x = x0; x <= x1; ++x) load({x, z});
  }
  void set(const BlockPos& p, const char* block) {
    if (const auto change = world.setBlock(p, defaultBlocks().id(block))) light.blockChanged(*change);
  }
  void fill(BlockPos a, BlockPos b, const char* block) {
    for (int y = a.y; y <= b.y; ++y)
      for (int z = a.z; z <= b.z; ++z)
        for (int x = a.x; x <= b.x; ++x) set({x, y, z}, block);
  }
  int block(const BlockPos& p) const { return light.lightAt(p, LightChannel::Block); }
  int sky(const BlockPos& p) const { return light.lightAt(p, LightChannel::Sky); }

  World world;
  LightEngine light;
  std::unique_ptr<ChunkGenerator> gen;
};

}  // namespace terrasol::testing
