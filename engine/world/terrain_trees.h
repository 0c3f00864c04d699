#pragma once
// The terrain generator's trees: forests of varying density, each tree of its biome's kind.

#include <cstdint>

#include "world/noise.h"
#include "world/terrain_stages.h"

namespace terrasol {

class TerrainTrees {
 public:
  explicit TerrainTrees(std::uint64_t seed) : forests_(seed ^ 0x08) {}

  // The trees of the chunk and its eight neighbours, each writing only the chunk's own blocks.
  void place(Chunk& chunk, const TerrainContext& t) const;

 private:
  Noise forests_;
};

}  // namespace terrasol
