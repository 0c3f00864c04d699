#pragma once
// Light computed from scratch, the simplest way we know, to check LightEngine's incremental updates
// against: the blocks of every loaded chunk are copied into one dense volume, sources are seeded, and
// light spreads level by level from 15 down (a bucket queue), each cell taking the best offer. It shares
// no code with engine/light.

#include <cstdint>
#include <string>
#include <vector>

#include "world/world.h"

namespace terrasol::testing {

class ReferenceLight {
 public:
  explicit ReferenceLight(const World& world);

  std::uint8_t block(const BlockPos& p) const { return block_[index(p)]; }
  std::uint8_t sky(const BlockPos& p) const { return sky_[index(p)]; }

 private:
  std::size_t index(const BlockPos& p) const {
    return (static_cast<std::size_t>(p.y - kMinY) * depth_ + static_cast<std::size_t>(p.z - z0_)) * width_ +
           static_cast<std::size_t>(p.x - x0_);
  }
  void spread(std::vector<std::uint8_t>& light) const;
  // Whether light cannot cross from cell i to its neighbour n in Direction d: the parts of the side
  // between them their shapes cover make up the whole side (BlockShapes::lightFaces).
  bool closed(std::size_t i, std::size_t n, int d) const;

  int x0_ = 0, z0_ = 0;
  std::size_t width_ = 0, depth_ = 0;
  std::vector<std::uint8_t> opacity_;  // 255: the cell's chunk is not loaded
  std::vector<std::uint8_t> sides_;    // BlockShapes::lightSides, bits by Direction
  std::vector<BlockId> state_;
  const BlockShapes* shapes_ = nullptr;
  std::vector<std::uint8_t> block_, sky_;
};

// Compares every cell of every loaded chunk; returns "" when all match, else the first mismatches.
std::string compareWithReference(const World& world);

}  // namespace terrasol::testing
