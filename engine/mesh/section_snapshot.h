#pragma once
// A copy of one 16³ section and the one-block halo around it (18³ cells): blocks, both light
// channels and the columns' tints, everything the mesher reads. Taken on the main thread from the World;
// meshed on any thread. Cells outside the world or in unloaded chunks read as air with no light (they are
// drawn against later, when their chunk loads and the section is remeshed).

#include <array>
#include <cstdint>
#include <optional>

#include "world/world.h"

namespace terrasol {

class SectionSnapshot {
 public:
  static constexpr int kSide = kChunkSize + 2;  // the section and its halo
  // Index of local cell (x, y, z), each -1..16.
  static constexpr int index(int x, int y, int z) { return ((y + 1) * kSide + (z + 1)) * kSide + (x + 1); }

  static constexpr int kCells = kSide * kSide * kSide;

  // A cell's light as smooth lighting sums it: block light in bits 0..3, sky light in bits 6..9 and
  // an open-cell count bit (1 << 12); 0 for an opaque cube, which does not count. Four of them add up
  // without carries, block and sky sums in bits 0..5 and 6..11 and the count in 12..14, so a face
  // corner's sum less one count is its vertex light field as PackedVertex stores it.
  static constexpr std::uint32_t kOpen = 1 << 12;
  static constexpr std::uint32_t lightTerm(bool opaque, int block, int sky) {
    return opaque ? 0 : kOpen | static_cast<std::uint32_t>(block) | static_cast<std::uint32_t>(sky) << 6;
  }

  SectionPos pos;
  std::array<BlockId, kCells> blocks;
  std::array<std::uint32_t, kCells> light;  // lightTerm per cell
  std::array<std::uint8_t, kCells> opaque;  // 1: an opaque cube (World::opaqueCubes)
  // The columns' tints (Chunk::tint), x and z -1..16 as in index(); a missing neighbour chunk
  // repeats this chunk's edge.
  std::array<ColumnTint, kSide * kSide> tints;
  const ColumnTint& tint(int x, int z) const {
    return tints[static_cast<std::size_t>((z + 1) * kSide + x + 1)];
  }
};

enum class CaptureResult { Captured, Empty, Buried };

// Fills `out` for section `pos`, unless the section can have no visible face: all air (Empty), or one
// opaque cube block throughout with every neighbouring cell across its six faces opaque too (Buried).
// Those two are decided from section uniformity and the six facing layers, without a per-block loop.
CaptureResult captureSection(const World& world, SectionPos pos, SectionSnapshot& out);

}  // namespace terrasol
