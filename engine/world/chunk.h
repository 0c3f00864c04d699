#pragma once
// A chunk: a 16 x 384 x 16 column of blocks (y from kMinY up to kMaxY), made of kSectionCount sections
// stacked bottom to top. Coordinates passed to a chunk are local in x and z (0..15) and absolute in y.

#include <array>

#include "world/biomes.h"
#include "world/chunk_light.h"
#include "world/coords.h"
#include "world/section.h"

namespace terrasol {

class Chunk {
 public:
  explicit Chunk(ChunkPos pos) : pos_(pos) {}

  ChunkPos pos() const { return pos_; }

  BlockId get(int x, int y, int z) const {
    if (!inWorldHeight(y)) return kAir;
    return sections_[sectionOf(y)].get(x, localOf(y), z);
  }
  // Returns the block that was there; outside the world height nothing changes and kAir is returned.
  BlockId set(int x, int y, int z, BlockId id) {
    if (!inWorldHeight(y)) return kAir;
    return sections_[sectionOf(y)].set(x, localOf(y), z, id);
  }

  Section& section(int index) { return sections_[static_cast<std::size_t>(index)]; }
  const Section& section(int index) const { return sections_[static_cast<std::size_t>(index)]; }

  // The y of the highest block in a column that is not air, or kMinY - 1; all-air sections are skipped.
  int highestBlock(int x, int z) const;

  // Frees the arrays of sections that have become uniform; returns the bytes still used.
  std::size_t compact();
  std::size_t memoryBytes() const;

  ChunkLight& light() { return light_; }
  const ChunkLight& light() const { return light_; }

  // Each column's biome tint, blended over its neighbourhood by the generator. Not saved: a loaded
  // chunk asks its generator again (ChunkGenerator::fillTints).
  const ColumnTint& tint(int x, int z) const { return tints_[static_cast<std::size_t>(columnIndex(x, z))]; }
  void setTint(int x, int z, const ColumnTint& tint) {
    tints_[static_cast<std::size_t>(columnIndex(x, z))] = tint;
  }

  // Edited since load or generation: must be saved before unloading.
  bool modified() const { return modified_; }
  void setModified(bool modified) { modified_ = modified; }

 private:
  ChunkPos pos_;
  std::array<Section, kSectionCount> sections_;
  ChunkLight light_;
  std::array<ColumnTint, kChunkArea> tints_{};
  bool modified_ = false;
};

}  // namespace terrasol
