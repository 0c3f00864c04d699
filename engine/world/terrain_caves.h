#pragma once
// The terrain generator's caves: 3D noise tunnels and caverns carved out of the shaped ground, open
// to the surface on land, lava at the bottom of the world.

#include <cstdint>

#include "world/noise.h"
#include "world/terrain_blocks.h"
#include "world/terrain_columns.h"

namespace terrasol {

class TerrainCaves {
 public:
  static constexpr int kLavaLevel = -54;  // caves at or below fill with lava

  explicit TerrainCaves(std::uint64_t seed);

  // Negative inside a cave. Pure; the same value carve() uses.
  double density(int x, int y, int z) const;
  // Whether a cave may open at height y in a column whose surface is at `surface`.
  static bool carveAllowed(int y, int surface);
  // Carves the chunk at `pos` through the ground of each column.
  void carve(ColumnBlocks& blocks, const ColumnSamples& columns, ChunkPos pos, const TerrainBlocks& b) const;

 private:
  // Density is evaluated on a lattice of 4 x 8 x 4 blocks and interpolated in between.
  static constexpr int kCellXZ = 4;
  static constexpr int kCellY = 8;

  double lattice(std::int64_t cx, std::int64_t cy, std::int64_t cz) const;

  Noise tunnelA_, tunnelB_, caverns_;
};

}  // namespace terrasol
