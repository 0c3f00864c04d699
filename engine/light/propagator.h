#pragma once
// The flood fill shared by every light update: one channel, a decrease queue, then an increase queue.
// Internal to engine/light.

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
  int section;
  int index;   // Section::index of the cell
  int column;  // z * 16 + x within the chunk
};

class Propagator {
 public:
  Propagator(const ChunkGrid& grid, LightChannel channel, const std::uint8_t* opacity, const std::uint8_t* emission,
             std::vector<LightEngine::Entry>& decrease, std::vector<LightEngine::Entry>& increase, LightStats& stats,
             std::unordered_set<std::uint64_t>& changed);

  bool locate(int x, int y, int z, Cell& cell) const {
    if (y < kMinY || y >= kMaxY) return false;
    Chunk* chunk = grid_.at(x, z);
    if (!chunk) return false;
    cell = {chunk, (y - kMinY) >> 4, Section::index(x & 15, y & 15, z & 15), (z & 15) * 16 + (x & 15)};
    return true;
  }
  std::uint8_t light(const Cell& c) const { return layer(c).get(c.index); }
  void setLight(const Cell& c, int x, int y, int z, std::uint8_t level);
  std::uint8_t opacity(const Cell& c) {
    ++stats_.blockReads;
    return opacity_[c.chunk->section(c.section).at(c.index)];
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
  NibbleArray& layer(const Cell& c) const {
    auto& light = c.chunk->light();
    return channel_ == LightChannel::Block ? light.block[static_cast<std::size_t>(c.section)]
                                           : light.sky[static_cast<std::size_t>(c.section)];
  }
  void runDecrease();
  void runIncrease();
  void markChanged(const Cell& c, int x, int y, int z);

  const ChunkGrid& grid_;
  LightChannel channel_;
  const std::uint8_t* opacity_;
  const std::uint8_t* emission_;
  std::vector<LightEngine::Entry>& decrease_;
  std::vector<LightEngine::Entry>& increase_;
  LightStats& stats_;
  std::unordered_set<std::uint64_t>& changed_;
  std::uint64_t lastChanged_ = ~0ull;
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
