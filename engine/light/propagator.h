#pragma once
// The flood fill shared by every light update: one channel, a decrease queue, then an increase queue.
// Internal to engine/light.

#include <array>
#include <vector>

#include "light/chunk_grid.h"
#include "light/light_engine.h"

namespace terrasol::light {

inline constexpr std::uint8_t kAllDirections = 0x3F;
constexpr std::uint8_t allBut(int direction) { return static_cast<std::uint8_t>(kAllDirections & ~(1 << direction)); }
constexpr int opposite(int direction) { return direction ^ 1; }  // West<->East, Down<->Up, North<->South

// Where a cell's data lives.
struct Cell {
  Chunk* chunk;
  NibbleArray* layer;     // the propagating channel's light of the cell's section
  const Section* blocks;  // the cell's section
  int section;
  int index;   // Section::index of the cell
  int column;  // z * 16 + x within the chunk
};

// Section::index and column steps per Direction, and whether a cell at local (x, y, z) has its
// neighbour in that direction inside the same section.
inline constexpr int kIndexStep[6] = {-1, 1, -256, 256, -16, 16};
inline constexpr int kColumnStep[6] = {-1, 1, 0, 0, -16, 16};
// Bit d set: the neighbour in Direction d is in the same section. Bit 6: the cell is inside (on no face).
inline const std::array<std::uint8_t, Section::kVolume> kInSection = [] {
  std::array<std::uint8_t, Section::kVolume> masks{};
  for (int i = 0; i < Section::kVolume; ++i) {
    const int x = i & 15, y = i >> 8, z = (i >> 4) & 15;
    const int m = (x != 0) | (x != 15) << 1 | (y != 0) << 2 | (y != 15) << 3 | (z != 0) << 4 | (z != 15) << 5;
    masks[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(m | (m == 0x3F) << 6);
  }
  return masks;
}();
inline bool staysInSection(int index, int direction) { return kInSection[static_cast<std::size_t>(index)] >> direction & 1; }

class Propagator {
 public:
  Propagator(const ChunkGrid& grid, LightChannel channel, const std::uint8_t* opacity, const std::uint8_t* emission,
             std::vector<LightEngine::Entry>& decrease, std::vector<LightEngine::Entry>& increase, LightStats& stats,
             std::unordered_set<std::uint64_t>& changed);

  bool locate(int x, int y, int z, Cell& cell) const {
    if (y < kMinY || y >= kMaxY) return false;
    Chunk* chunk = grid_.at(x, z);
    if (!chunk) return false;
    const int section = (y - kMinY) >> 4;
    cell = {chunk, &layerOf(chunk, section), &chunk->section(section), section,
            Section::index(x & 15, y & 15, z & 15), (z & 15) * 16 + (x & 15)};
    return true;
  }
  // The neighbour of `c` (at x, y, z) in `direction`; most steps stay in the section and need no lookup.
  bool neighbour(const Cell& c, int direction, int x, int y, int z, Cell& n) const {
    if (staysInSection(c.index, direction)) {
      n = c;
      n.index += kIndexStep[direction];
      n.column += kColumnStep[direction];
      return true;
    }
    return locate(x, y, z, n);
  }
  std::uint8_t light(const Cell& c) const { return c.layer->get(c.index); }
  void setLight(const Cell& c, int x, int y, int z, std::uint8_t level) {
    c.layer->set(c.index, level);
    ++stats_.lightWrites;
    if (kInSection[static_cast<std::size_t>(c.index)] & 0x40) {
      marks_[static_cast<std::size_t>((((z >> 4) - grid_.minZ() + 1) * marksWidth_ + (x >> 4) - grid_.minX() + 1) * kSectionCount + c.section)] = 1;
    } else {
      markChanged(c, x, y, z);
    }
  }
  std::uint8_t opacity(const Cell& c) {
    ++stats_.blockReads;
    return opacity_[c.blocks->at(c.index)];
  }
  // The level a cell has by itself: its emission (block light) or 15 in the open sky column (sky light).
  std::uint8_t source(const Cell& c, int y);

  void decrease(int x, int y, int z, std::uint8_t level, std::uint8_t directions) {
    decrease_.push_back({x, y, z, level, directions});
  }
  void increase(int x, int y, int z, std::uint8_t level, std::uint8_t directions) {
    increase_.push_back({x, y, z, level, directions});
  }
  // Runs the decrease queue, then the increase queue (which the decreases add to), to the end.
  void run();

 private:
  NibbleArray& layerOf(Chunk* chunk, int section) const {
    auto& light = chunk->light();
    return channel_ == LightChannel::Block ? light.block[static_cast<std::size_t>(section)]
                                           : light.sky[static_cast<std::size_t>(section)];
  }
  void runDecrease();
  void runIncrease();
  void markChanged(const Cell& c, int x, int y, int z);
  void flushChanged();

  const ChunkGrid& grid_;
  LightChannel channel_;
  const std::uint8_t* opacity_;
  const std::uint8_t* emission_;
  std::vector<LightEngine::Entry>& decrease_;
  std::vector<LightEngine::Entry>& increase_;
  LightStats& stats_;
  std::unordered_set<std::uint64_t>& changed_;
  // One flag per section of the grid plus a one-chunk margin (halos reach into the next chunk), so
  // marking a change on the hot path is a byte store; flushChanged() turns them into keys.
  int marksWidth_, marksDepth_;
  std::vector<std::uint8_t> marks_;
};

// Key of a section in LightEngine's changed set: 27 bits each of chunk x and z (the world border is
// at chunk +-1 875 000, well inside +-2^26) and 5 bits of section index.
constexpr std::uint64_t sectionKey(int chunkX, int section, int chunkZ) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(chunkX) & 0x7FFFFFF) << 32) |
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(chunkZ) & 0x7FFFFFF) << 5) |
         static_cast<std::uint64_t>(section & 31);
}
constexpr SectionPos sectionFromKey(std::uint64_t key) {
  auto signExtend27 = [](std::uint64_t v) { return static_cast<int>(static_cast<std::int32_t>(static_cast<std::uint32_t>(v << 5)) >> 5); };
  return {signExtend27((key >> 32) & 0x7FFFFFF), static_cast<int>(key & 31), signExtend27((key >> 5) & 0x7FFFFFF)};
}
static_assert(sectionFromKey(sectionKey(-1'875'000, 23, 1'875'000)) == SectionPos{-1'875'000, 23, 1'875'000});

}  // namespace terrasol::light
