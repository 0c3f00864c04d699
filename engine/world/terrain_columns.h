#pragma once
// What the terrain generator's column stages work on: each column's surface and biome, sampled once,
// and the chunk's blocks in one buffer laid out like its sections stacked bottom to top, copied into
// the chunk when shaping and carving are done.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "world/biomes.h"
#include "world/chunk.h"

namespace terrasol {

struct ColumnSample {
  int surface = 0;  // the highest ground block (TerrainShape::surfaceHeight)
  Biome biome{};
};
// By columnIndex.
using ColumnSamples = std::array<ColumnSample, kChunkArea>;

class ColumnBlocks {
 public:
  BlockId& at(int x, int y, int z) { return blocks_[index(x, y, z)]; }
  BlockId at(int x, int y, int z) const { return blocks_[index(x, y, z)]; }

  // Laid out exactly like kSectionCount consecutive sections.
  static constexpr std::size_t index(int x, int y, int z) {
    return static_cast<std::size_t>(y - kMinY) * kChunkArea + static_cast<std::size_t>(z) * kChunkSize +
           static_cast<std::size_t>(x);
  }

  void copyTo(Chunk& chunk) const {
    for (int s = 0; s < kSectionCount; ++s) {
      Section& section = chunk.section(s);
      std::copy_n(blocks_.begin() + static_cast<std::ptrdiff_t>(s) * Section::kVolume, Section::kVolume,
                  section.mutableBlocks().begin());
      section.compact();
    }
  }

 private:
  std::vector<BlockId> blocks_ =
      std::vector<BlockId>(static_cast<std::size_t>(kSectionCount) * Section::kVolume, kAir);
};
static_assert(ColumnBlocks::index(3, kMinY + kChunkSize + 1, 5) ==
              Section::kVolume + Section::index(3, 1, 5));

}  // namespace terrasol
