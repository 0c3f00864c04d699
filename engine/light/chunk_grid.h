#pragma once
// A rectangle of chunk pointers around an update, so propagation finds a cell's chunk with two
// subtractions and an index instead of a hash lookup. Built per update: an update reaches at most 30
// blocks from its seeds (15 steps of removal, then 15 of refill), so seeds' chunks +-2 cover it.
// Internal to engine/light.

#include <vector>

#include "world/world.h"

namespace terrasol::light {

class ChunkGrid {
 public:
  // Chunks from min to max inclusive; `excluded` (a chunk being unloaded) counts as not loaded.
  ChunkGrid(World& world, ChunkPos min, ChunkPos max, const Chunk* excluded = nullptr)
      : minX_(min.x), minZ_(min.z), width_(max.x - min.x + 1), depth_(max.z - min.z + 1) {
    chunks_.resize(static_cast<std::size_t>(width_ * depth_));
    for (int z = 0; z < depth_; ++z)
      for (int x = 0; x < width_; ++x) {
        Chunk* c = world.chunk({minX_ + x, minZ_ + z});
        chunks_[static_cast<std::size_t>(z * width_ + x)] = (c && c != excluded && c->light().lit) ? c : nullptr;
      }
  }

  // The chunk holding block column (x, z), or null when it is outside the grid or not lit.
  Chunk* at(int x, int z) const {
    const unsigned gx = static_cast<unsigned>((x >> 4) - minX_), gz = static_cast<unsigned>((z >> 4) - minZ_);
    if (gx >= static_cast<unsigned>(width_) || gz >= static_cast<unsigned>(depth_)) return nullptr;
    return chunks_[gz * static_cast<unsigned>(width_) + gx];
  }

  int minX() const { return minX_; }
  int minZ() const { return minZ_; }
  int width() const { return width_; }
  int depth() const { return depth_; }

 private:
  int minX_, minZ_, width_, depth_;
  std::vector<Chunk*> chunks_;
};

}  // namespace terrasol::light
