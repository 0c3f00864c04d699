#pragma once
// A copy of one 16³ section and the one-block halo around it (18³ cells): blocks and both light
// channels, everything the mesher reads. Taken on the main thread from the World; meshed on any
// thread. Cells outside the world or in unloaded chunks read as air with no light (they are drawn
// against later, when their chunk loads and the section is remeshed).

#include <array>
#include <cstdint>
#include <optional>

#include "world/world.h"

namespace terrasol {

class SectionSnapshot {
 public:
  static constexpr int kSide = 18;
  // Index of local cell (x, y, z), each -1..16.
  static constexpr int index(int x, int y, int z) { return ((y + 1) * kSide + (z + 1)) * kSide + (x + 1); }

  static constexpr int kCells = kSide * kSide * kSide;

  // A cell's light as smooth lighting sums it: kOpen | sky light << 6 | block light, and 0 for an
  // opaque cube (it does not count). Four of them add up without carries: each field holds 4 x 15.
  static constexpr std::uint16_t kOpen = 1 << 12;
  static constexpr std::uint16_t lightTerm(bool opaque, int block, int sky) {
    return opaque ? 0 : static_cast<std::uint16_t>(kOpen | sky << 6 | block);
  }
  int blockLight(int i) const { return light[static_cast<std::size_t>(i)] & 63; }
  int skyLight(int i) const { return light[static_cast<std::size_t>(i)] >> 6 & 63; }

  SectionPos pos;
  std::array<BlockId, kCells> blocks;
  std::array<std::uint16_t, kCells> light;  // lightTerm per cell
  std::array<std::uint8_t, kCells> opaque;  // 1: an opaque cube (BlockRegistry::opaqueCubes)
};

enum class CaptureResult { Captured, Empty, Buried };

// Fills `out` for section `pos`, unless the section can have no visible face: all air (Empty), or one
// opaque cube block throughout with every neighbouring cell across its six faces opaque too (Buried).
// Those two are decided from section uniformity and the six facing layers, without a per-block loop.
CaptureResult captureSection(const World& world, SectionPos pos, SectionSnapshot& out);

}  // namespace terrasol
