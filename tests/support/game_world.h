#pragma once
// Worlds for the game's logic tests: a stone floor around the origin, and the default pack's shapes.

#include <memory>

#include "scene/block_atlas.h"
#include "support/world_support.h"
#include "world/world.h"

namespace terrasol::testing {

// Loaded chunks around the origin: stone up to y = 63 (the floor's top face at y = 64).
inline World flatWorld(int radius = 3) {
  World world(defaultBlocks());
  const BlockId stone = defaultBlocks().id("stone");
  for (int cz = -radius; cz <= radius; ++cz)
    for (int cx = -radius; cx <= radius; ++cx) {
      auto chunk = std::make_unique<Chunk>(ChunkPos{cx, cz});
      for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x)
          for (int y = 0; y < 64; ++y) chunk->set(x, y, z, stone);
      world.insertChunk(std::move(chunk));
    }
  return world;
}

// The default pack's shapes: slabs and stairs collide as their models are built.
inline const BlockShapes& defaultShapes() {
  static const BlockShapes shapes = defaultPackShapes(defaultBlocks());
  return shapes;
}

}  // namespace terrasol::testing
