#include "light/propagator.h"

#include <algorithm>
#include <bit>

namespace terrasol::light {

Propagator::Propagator(LightFrame& frame, const ChunkWindow& window, LightChannel channel, const std::uint8_t* opacity,
                       const std::uint8_t* emission, std::vector<LightEngine::Entry>& decrease,
                       std::vector<LightEngine::Entry>& increase, LightStats& stats,
                       std::unordered_set<std::uint64_t>& changed)
    : frame_(frame),
      channel_(channel),
      opacity_(opacity),
      emission_(emission),
      decrease_(decrease),
      increase_(increase),
      stats_(stats),
      changed_(changed) {
  frame_.reset(window, channel);
  decrease_.clear();
  increase_.clear();
}

Propagator::~Propagator() {
  stats_.blockReads += blockReads_;
  stats_.lightWrites += lightWrites_;
}

std::uint8_t Propagator::source(const SectionRef& r, int index, std::uint32_t pos) {
  if (channel_ == LightChannel::Block) {
    ++blockReads_;
    return emission_[r.blocks[index & r.blockMask]];
  }
  const int y = LightFrame::worldY(pos);
  if (y > r.skyTop[index & 255]) return 15;
  // The top layer of the world is lit from the sky above it, through its own opacity.
  if (y == kMaxY - 1) return static_cast<std::uint8_t>(15 - std::max<int>(1, opacity(r, index)));
  return 0;
}

// A written cell changes its own section's mesh and, on a face, the halo of the sections beside it.
void Propagator::flushChanged() {
  for (const int chunk : frame_.resolvedChunks()) {
    SectionRef* refs = frame_.chunkRefs(chunk);
    const int cx = frame_.minX() + chunk % frame_.width(), cz = frame_.minZ() + chunk / frame_.width();
    for (int s = 0; s < kSectionCount; ++s) {
      const std::uint8_t m = refs[s].marks;
      if (!m) continue;
      refs[s].marks = 0;
      const int y0 = (m & 4) && s > 0 ? -1 : 0, y1 = (m & 8) && s < kSectionCount - 1 ? 1 : 0;
      for (int dz = -(m >> 4 & 1); dz <= (m >> 5 & 1); ++dz)
        for (int dx = -(m & 1); dx <= (m >> 1 & 1); ++dx)
          for (int dy = y0; dy <= y1; ++dy) changed_.insert(sectionKey(cx + dx, s + dy, cz + dz));
    }
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
    // The cell itself may be in a chunk being unloaded: its position still leads to its neighbours.
    Cell c{&frame_.ref(frame_.refIndex(e.pos)), LightFrame::local(e.pos), e.pos};
    const bool here = c.ref->layer != nullptr;
    // A cell of a chunk being unloaded: no in-section shortcut, every step is looked up.
    const std::uint8_t inSection = here ? kInSection[static_cast<std::size_t>(c.index)] : 0;
    for (unsigned dirs = e.directions; dirs != 0; dirs &= dirs - 1) {
      const int d = std::countr_zero(dirs);
      Cell n;
      if (!step(c, inSection, d, n)) continue;
      const std::uint8_t level = light(n);
      if (level == 0) continue;
      if (level < e.level) {
        const std::uint8_t own = source(n);
        if (own < level) {
          // Its light may have come through the removed cell: clear it and keep removing from it.
          setLight(n, own);
          decrease_.push_back({n.pos, level, allBut(opposite(d))});
          if (own > 0) increase_.push_back({n.pos, own, kAllDirections});
          continue;
        }
      }
      // Light of its own or from elsewhere: it refills the cleared cells afterwards.
      increase_.push_back({n.pos, level, kAllDirections});
    }
  }
}

void Propagator::runIncrease() {
  for (std::size_t head = 0; head < increase_.size(); ++head) {
    const LightEngine::Entry e = increase_[head];
    Cell c;
    if (!locate(e.pos, c) || light(c) != e.level) continue;  // superseded since it was queued
    const std::uint8_t inSection = kInSection[static_cast<std::size_t>(c.index)];
    for (unsigned dirs = e.directions; dirs != 0; dirs &= dirs - 1) {
      const int d = std::countr_zero(dirs);
      Cell n;
      if (!step(c, inSection, d, n)) continue;
      const std::uint8_t current = light(n);
      if (current + 1 >= e.level) continue;  // cannot improve even through air: no block read needed
      const int level = e.level - std::max<int>(1, opacity(*n.ref, n.index));
      if (level <= current) continue;
      setLight(n, static_cast<std::uint8_t>(level));
      if (level > 1) increase_.push_back({n.pos, static_cast<std::uint8_t>(level), allBut(opposite(d))});
    }
  }
}

}  // namespace terrasol::light
