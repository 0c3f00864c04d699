#pragma once
// The terrain generator's trees: forests of varying density, each tree of its biome's kind.

#include <cstdint>
#include <vector>

#include "world/generator.h"
#include "world/noise.h"
#include "world/terrain_stages.h"

namespace terrasol {

class TerrainTrees {
 public:
  explicit TerrainTrees(std::uint64_t seed) : forests_(seed ^ 0x08) {}

  // The trees of the chunk and its eight neighbours, each writing only the chunk's own blocks.
  void place(Chunk& chunk, const TerrainContext& t) const;
  // The crowns of the trees rooted in chunk `at`, as place() would grow them.
  void crowns(ChunkPos at, const TerrainContext& t, std::vector<TreeCrown>& out) const;

 private:
  // Calls f(x, ground, z, hash, biome) for each tree rooted in chunk `at`.
  template <class F>
  void forEachTree(ChunkPos at, const TerrainContext& t, F&& f) const;

  Noise forests_;
};

}  // namespace terrasol
