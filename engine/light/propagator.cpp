#include "light/propagator.h"

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
      changed_(changed) {
  decrease_.clear();
  increase_.clear();
}

std::uint8_t Propagator::source(const Cell& c, int y) {
  if (channel_ == LightChannel::Block) {
    ++stats_.blockReads;
    return emission_[c.chunk->section(c.section).at(c.index)];
  }
  if (y > c.chunk->light().skyTop[static_cast<std::size_t>(c.column)]) return 15;
  // The top layer of the world is lit from the sky above it, through its own opacity.
  if (y == kMaxY - 1) return static_cast<std::uint8_t>(15 - std::max<int>(1, opacity(c)));
  return 0;
}

void Propagator::setLight(const Cell& c, int x, int y, int z, std::uint8_t level) {
  layer(c).set(c.index, level);
  ++stats_.lightWrites;
  markChanged(c, x, y, z);
}

// Marks the cell's section and, for a cell on a section face, the sections whose one-block halo holds it.
void Propagator::markChanged(const Cell& c, int x, int y, int z) {
  const int cx = x >> 4, cz = z >> 4;
  const std::uint64_t key = sectionKey(cx, c.section, cz);
  const int lx = x & 15, ly = y & 15, lz = z & 15;
  const bool onFace = lx == 0 || lx == 15 || ly == 0 || ly == 15 || lz == 0 || lz == 15;
  if (!onFace) {
    if (key != lastChanged_) changed_.insert(key);
    lastChanged_ = key;
    return;
  }
  lastChanged_ = ~0ull;
  const int x0 = lx == 0 ? -1 : 0, x1 = lx == 15 ? 1 : 0;
  const int y0 = ly == 0 && c.section > 0 ? -1 : 0, y1 = ly == 15 && c.section < kSectionCount - 1 ? 1 : 0;
  const int z0 = lz == 0 ? -1 : 0, z1 = lz == 15 ? 1 : 0;
  for (int dz = z0; dz <= z1; ++dz)
    for (int dy = y0; dy <= y1; ++dy)
      for (int dx = x0; dx <= x1; ++dx) changed_.insert(sectionKey(cx + dx, c.section + dy, cz + dz));
}

void Propagator::run() {
  runDecrease();
  runIncrease();
}

void Propagator::runDecrease() {
  for (std::size_t head = 0; head < decrease_.size(); ++head) {
    const LightEngine::Entry e = decrease_[head];
    for (int d = 0; d < 6; ++d) {
      if (!(e.directions & (1 << d))) continue;
      const BlockPos& o = kDirectionOffsets[d];
      const int x = e.x + o.x, y = e.y + o.y, z = e.z + o.z;
      Cell n;
      if (!locate(x, y, z, n)) continue;
      const std::uint8_t level = light(n);
      if (level == 0) continue;
      const std::uint8_t own = source(n, y);
      if (level < e.level && own < level) {
        // Its light may have come through the removed cell: clear it and keep removing from it.
        setLight(n, x, y, z, own);
        decrease(x, y, z, level, allBut(opposite(d)));
        if (own > 0) increase(x, y, z, own, kAllDirections);
      } else {
        // Light of its own or from elsewhere: it refills the cleared cells afterwards.
        increase(x, y, z, level, kAllDirections);
      }
    }
  }
}

void Propagator::runIncrease() {
  for (std::size_t head = 0; head < increase_.size(); ++head) {
    const LightEngine::Entry e = increase_[head];
    Cell c;
    if (!locate(e.x, e.y, e.z, c) || light(c) != e.level) continue;  // superseded since it was queued
    for (int d = 0; d < 6; ++d) {
      if (!(e.directions & (1 << d))) continue;
      const BlockPos& o = kDirectionOffsets[d];
      const int x = e.x + o.x, y = e.y + o.y, z = e.z + o.z;
      Cell n;
      if (!locate(x, y, z, n)) continue;
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
