#pragma once
// One section's light solved in plain bytes, for LightEngine::relightSection: every cell starts at its
// own level, the light around the section is offered across its faces, and the flood fill runs inside
// the section, highest level first, so each cell spreads once, at its final level. No nibbles, no
// frame positions: a step is an index step. Opacities are read on first need and kept for the other
// channel. Internal to engine/light.

#include <array>
#include <cstdint>

#include "core/light_level.h"
#include "world/section.h"

namespace terrasol::light {

// Per Direction d, the kChunkArea cells on a section's face in d: each one's index, and the index of the cell
// beyond it in the neighbouring section.
struct FaceCell {
  std::uint16_t ours, theirs;
};
inline const std::array<std::array<FaceCell, kChunkArea>, 6> kFaceCells = [] {
  std::array<std::array<FaceCell, kChunkArea>, 6> faces{};
  for (int d = 0; d < 6; ++d)
    for (int a = 0; a < kChunkSize; ++a)
      for (int b = 0; b < kChunkSize; ++b) {
        const int axis = d >> 1, near = d & 1 ? kLastCell : 0, far = kLastCell - near;
        const int x = axis == 0 ? near : a,
                  y = axis == 1   ? near
                      : axis == 0 ? a
                                  : b,
                  z = axis == 2 ? near : b;
        const int fx = axis == 0 ? far : x, fy = axis == 1 ? far : y, fz = axis == 2 ? far : z;
        faces[static_cast<std::size_t>(d)][static_cast<std::size_t>(a * kChunkSize + b)] = {
            static_cast<std::uint16_t>(Section::index(x, y, z)),
            static_cast<std::uint16_t>(Section::index(fx, fy, fz))};
      }
  return faces;
}();

class SectionSolver {
 public:
  using Levels = std::array<std::uint8_t, Section::kVolume>;

  // A new section, whose blocks are blocks[index & mask]: forgets the opacities read so far.
  void begin(const BlockId* blocks, int mask, const std::uint8_t* attenuations);
  // A new channel: fill levels() with every cell's own level, then seed and offer.
  Levels& levels() { return levels_; }
  // Cell `index` spreads its own level (call once per cell, before solve).
  void seed(int index) { push(levels_[static_cast<std::size_t>(index)], index); }
  // Light `level` in the cell just outside face cell `index` enters it.
  void offer(int index, int level) { enter(index, level); }
  // Spreads every seeded level through the section: levels() then holds the section's light.
  void solve();
  // Block ids read since begin().
  std::uint64_t reads() const { return reads_; }

 private:
  // max(1, opacity) of the cell's block, read once per section.
  int attenuation(int index) {
    std::uint8_t& a = attenuation_[static_cast<std::size_t>(index)];
    if (a == 0) {
      ++reads_;
      a = attenuations_[blocks_[index & mask_]];
    }
    return a;
  }
  // Light `from` next to cell `index` raises it to from - attenuation where that is brighter.
  void enter(int index, int from) {
    const int current = levels_[static_cast<std::size_t>(index)];
    if (current + 1 >= from) return;  // no block read: not even air would let it brighten
    const int level = from - attenuation(index);
    if (level <= current) return;
    levels_[static_cast<std::size_t>(index)] = static_cast<std::uint8_t>(level);
    push(level, index);
  }
  void push(int level, int index) {
    if (level < 2) return;  // a level of 1 gives its neighbours nothing
    buckets_[static_cast<std::size_t>(level)][counts_[level]++] = static_cast<std::uint16_t>(index);
  }

  const BlockId* blocks_ = nullptr;
  int mask_ = 0;
  const std::uint8_t* attenuations_ = nullptr;  // by block id (attenuations())
  std::uint64_t reads_ = 0;
  Levels levels_{};
  Levels attenuation_{};  // 0 until read
  // Cells waiting to spread, by level. A cell enters a level's bucket at most once (it only rises),
  // so a bucket never holds more than a section's cells.
  std::array<std::array<std::uint16_t, Section::kVolume>, kLightLevels> buckets_{};
  int counts_[kLightLevels] = {};
};

}  // namespace terrasol::light
