#include "light/propagator.h"

#include <bit>

namespace terrasol::light {

Propagator::Propagator(const ChunkGrid& grid, LightChannel channel, const std::uint8_t* opacity,
                       const std::uint8_t* emission, std::vector<LightEngine::Entry>& decrease,
                       std::vector<LightEngine::Entry>& increase, LightStats& stats,
                       std::unordered_set<std::uint64_t>& changed)
    : grid_(grid),
      channel_(channel),
      opacity_(opacity),
      emission_(emission),
      decrease_(decrease),
      increase_(increase),
      stats_(stats),
      changed_(changed),
      marksWidth_(grid.width() + 2),
      marksDepth_(grid.depth() + 2),
      marks_(static_cast<std::size_t>(marksWidth_ * marksDepth_ * kSectionCount), 0) {
  decrease_.clear();
  increase_.clear();
}

std::uint8_t Propagator::source(const Cell& c, int y) {
  if (channel_ == LightChannel::Block) {
    ++stats_.blockReads;
    return emission_[c.blocks->at(c.index)];
  }
  if (y > c.chunk->light().skyTop[static_cast<std::size_t>(c.column)]) return 15;
  // The top layer of the world is lit from the sky above it, through its own opacity.
  if (y == kMaxY - 1) return static_cast<std::uint8_t>(15 - std::max<int>(1, opacity(c)));
  return 0;
}

// Marks the cell's section and, for a cell on a section face, the sections whose one-block halo holds it.
void Propagator::markChanged(const Cell& c, int x, int y, int z) {
  const int gx = (x >> 4) - grid_.minX() + 1, gz = (z >> 4) - grid_.minZ() + 1;  // inside the margin
  const int lx = x & 15, ly = y & 15, lz = z & 15;
  const int x0 = lx == 0 ? -1 : 0, x1 = lx == 15 ? 1 : 0;
  const int y0 = ly == 0 && c.section > 0 ? -1 : 0, y1 = ly == 15 && c.section < kSectionCount - 1 ? 1 : 0;
  const int z0 = lz == 0 ? -1 : 0, z1 = lz == 15 ? 1 : 0;
  for (int dz = z0; dz <= z1; ++dz)
    for (int dx = x0; dx <= x1; ++dx) {
      std::uint8_t* column = &marks_[static_cast<std::size_t>(((gz + dz) * marksWidth_ + gx + dx) * kSectionCount)];
      for (int dy = y0; dy <= y1; ++dy) column[c.section + dy] = 1;
    }
}

void Propagator::flushChanged() {
  for (int gz = 0; gz < marksDepth_; ++gz)
    for (int gx = 0; gx < marksWidth_; ++gx)
      for (int s = 0; s < kSectionCount; ++s) {
        std::uint8_t& mark = marks_[static_cast<std::size_t>((gz * marksWidth_ + gx) * kSectionCount + s)];
        if (!mark) continue;
        mark = 0;
        changed_.insert(sectionKey(grid_.minX() - 1 + gx, s, grid_.minZ() - 1 + gz));
      }
}

void Propagator::run() {
  runDecrease();
  runIncrease();
  flushChanged();
}

void Propagator::runDecrease() {
  for (std::size_t head = 0; head < decrease_.size(); ++head) {
    const LightEngine::Entry e = decrease_[head];
    Cell c;
    // The cell itself may be gone (a chunk unloading): then every step needs a lookup.
    const bool here = locate(e.x, e.y, e.z, c);
    for (unsigned dirs = e.directions; dirs != 0; dirs &= dirs - 1) {
      const int d = std::countr_zero(dirs);
      const BlockPos& o = kDirectionOffsets[d];
      const int x = e.x + o.x, y = e.y + o.y, z = e.z + o.z;
      Cell n;
      if (!(here ? neighbour(c, d, x, y, z, n) : locate(x, y, z, n))) continue;
      const std::uint8_t level = light(n);
      if (level == 0) continue;
      if (level < e.level) {
        const std::uint8_t own = source(n, y);
        if (own < level) {
          // Its light may have come through the removed cell: clear it and keep removing from it.
          setLight(n, x, y, z, own);
          decrease(x, y, z, level, allBut(opposite(d)));
          if (own > 0) increase(x, y, z, own, kAllDirections);
          continue;
        }
      }
      // Light of its own or from elsewhere: it refills the cleared cells afterwards.
      increase(x, y, z, level, kAllDirections);
    }
  }
}

void Propagator::runIncrease() {
  for (std::size_t head = 0; head < increase_.size(); ++head) {
    const LightEngine::Entry e = increase_[head];
    Cell c;
    if (!locate(e.x, e.y, e.z, c) || light(c) != e.level) continue;  // superseded since it was queued
    for (unsigned dirs = e.directions; dirs != 0; dirs &= dirs - 1) {
      const int d = std::countr_zero(dirs);
      const BlockPos& o = kDirectionOffsets[d];
      const int x = e.x + o.x, y = e.y + o.y, z = e.z + o.z;
      Cell n;
      if (!neighbour(c, d, x, y, z, n)) continue;
      const std::uint8_t current = light(n);
      if (current + 1 >= e.level) continue;  // cannot improve even through air: no block read needed
      const int level = e.level - std::max<int>(1, opacity(n));
      if (level <= current) continue;
      setLight(n, x, y, z, static_cast<std::uint8_t>(level));
      if (level > 1) increase(x, y, z, static_cast<std::uint8_t>(level), allBut(opposite(d)));
    }
  }
}

}  // namespace terrasol::light
