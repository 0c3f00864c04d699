#include "light/propagator.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "light/level_words.h"

namespace terrasol::light {

Propagator::Propagator(LightFrame& frame, const ChunkWindow& window, LightChannel channel,
                       const std::uint8_t* attenuation, const LightFaces& faces, const std::uint8_t* emission,
                       std::vector<LightEngine::Entry>& decrease, std::vector<LightEngine::Entry>& increase,
                       LightStats& stats, ChangedSections& changed)
    : frame_(frame),
      channel_(channel),
      attenuation_(attenuation),
      faces_(faces),
      emission_(emission),
      decrease_(decrease),
      increase_(increase),
      stats_(stats),
      changed_(changed) {
  frame_.reset(window, channel);
}

Propagator::~Propagator() {
  stats_.blockReads += blockReads_;
  stats_.lightWrites += lightWrites_;
}

void Propagator::replaceLevels(SectionRef& r, std::uint32_t origin, const std::uint8_t* levels) {
  std::uint8_t* current = r.levelBytes();
  int writes = 0;
  for (int q = 0; q < kByteWords; ++q) {
    const std::uint64_t before = byteWord(current, q), after = byteWord(levels, q);
    if (before == after) continue;
    const std::uint64_t changed = changedBytes(before, after);
    writes += std::popcount(changed);
    r.marks |= writeMarksOfBytes(q, changed);
    // Light that left through a face cell that lost some may have lit cells beyond it.
    for (std::uint64_t lost = lowerBytes(before, after) & faceBytes(q); lost != 0; lost &= lost - 1) {
      const int k = q * 8 + std::countr_zero(lost) / 8;
      decrease(posOf(origin, k), current[k],
               static_cast<std::uint8_t>(kWriteMarks[static_cast<std::size_t>(k)] & kAllDirections));
    }
  }
  if (writes == 0) return;
  lightWrites_ += static_cast<std::uint64_t>(writes);
  std::memcpy(frame_.own(r), levels, Section::kVolume);
}

// Written sections are packed back. A changed cell changes its own section's mesh and, on a face,
// the halo of the sections beside it.
void Propagator::writeBack() {
  for (const int chunk : frame_.resolvedChunks()) {
    SectionRef* refs = frame_.chunkRefs(chunk);
    const ChunkPos at = frame_.chunkPos(chunk);
    const int cx = at.x, cz = at.z;
    for (int s = 0; s < kSectionCount; ++s) {
      const int m = static_cast<int>(frame_.pack(refs[s + 1]));
      if (!m) continue;
      const int y0 = (m & kDownFace) && s > 0 ? -1 : 0, y1 = (m & kUpFace) && s < kSectionCount - 1 ? 1 : 0;
      for (int dz = -hasFace(m, Direction::North); dz <= hasFace(m, Direction::South); ++dz)
        for (int dx = -hasFace(m, Direction::West); dx <= hasFace(m, Direction::East); ++dx)
          for (int dy = y0; dy <= y1; ++dy) changed_.add(cx + dx, s + dy, cz + dz);
    }
  }
}

void Propagator::run() {
  runDecrease();
  runIncrease();
  writeBack();
}

// Calls visit(cursor, index, pos, d) for each neighbour of the entry's cell in `directions` (all six
// for a cell inside its section) that is in the frame and loaded: those in the cell's own section
// through one cursor, the others each through their own. A cell that is not loaded (a chunk being
// unloaded) still leads across its faces.
template <class Visit>
void Propagator::forNeighbours(SectionRef& r, Cursor& own, CellIndex index, std::uint32_t pos,
                               std::uint8_t inSection, unsigned directions, Visit&& visit) {
  // The neighbours in `near`, all in this section, through its cursor: unrolled, a branch per
  // direction, which costs less than a loop over the bits (and nothing where `near` is a constant).
  auto visitInSection = [&](unsigned near) {
    Cursor& c = own;
    constexpr int kRow = kChunkSize, kLayer = kChunkArea;  // index steps along z and y
    if (near & kWestFace) visit(c, index - 1, pos - 1, 0);
    if (near & kEastFace) visit(c, index + 1, pos + 1, 1);
    if (near & kDownFace) visit(c, index - kLayer, pos - kLayer, 2);
    if (near & kUpFace) visit(c, index + kLayer, pos + kLayer, 3);
    if (near & kNorthFace) visit(c, index - kRow, pos - kRow, 4);
    if (near & kSouthFace) visit(c, index + kRow, pos + kRow, 5);
  };
  if ((inSection & kInterior) && r.layer) {
    // All six, the direction the entry came from too (it cannot change: it is at least as bright).
    visitInSection(kAllDirections);
    return;
  }
  if (const unsigned near = directions & inSection; near && r.layer) visitInSection(near);
  for (unsigned dirs = directions & ~inSection & kAllDirections; dirs != 0; dirs &= dirs - 1) {
    const int d = std::countr_zero(dirs);
    Cell n;
    if (!locate(frame_.across(pos, d), n)) continue;
    Cursor c(*n.ref);
    visit(c, n.index, n.pos, d);
    c.flush();
  }
}

void Propagator::runDecrease() {
  if (decrease_.size() == 0) return;
  const std::size_t queued = decrease_.size();  // each cell cleared is queued: writes are the growth
  std::uint64_t reads = 0;
  Cursor own(frame_.queuedRef(LightFrame::refIndex(decrease_[0].pos)));
  for (std::size_t head = 0; head < decrease_.size(); ++head) {
    const LightEngine::Entry e = decrease_[head];
    // The cell itself may be in a chunk being unloaded: its position still leads to its neighbours,
    // each looked up on its own.
    SectionRef& r = frame_.queuedRef(LightFrame::refIndex(e.pos));
    if (&r != own.ref) {
      own.flush();
      own = Cursor(r);
    }
    const CellIndex index = LightFrame::local(e.pos);
    const std::uint8_t inSection = kInSection[static_cast<std::size_t>(index)];
    LightEngine::Entry* darker = decrease_.room(6);
    LightEngine::Entry* refill = increase_.room(6);
    std::size_t darkerCount = 0, refillCount = 0;
    forNeighbours(r, own, index, e.pos, inSection, e.directions,
                  [&](Cursor& c, CellIndex i, std::uint32_t pos, int d) {
                    const std::uint8_t level = c.light(i);
                    if (level == 0) return;
                    if (level < e.level) {
                      const std::uint8_t own = source(c, i, reads);
                      if (own < level) {
                        // Its light may have come through the removed cell: clear it, remove on from it.
                        c.set(frame_, i, own);
                        darker[darkerCount++] = {pos, level, allBut(opposite(d))};
                        if (own > 0) refill[refillCount++] = {pos, own, kAllDirections};
                        return;
                      }
                    }
                    // Light of its own or from elsewhere: it refills the cleared cells afterwards.
                    refill[refillCount++] = {pos, level, kAllDirections};
                  });
    decrease_.commit(darkerCount);
    increase_.commit(refillCount);
  }
  own.flush();
  blockReads_ += reads;
  lightWrites_ += decrease_.size() - queued;
}

void Propagator::runIncrease() {
  if (increase_.size() == 0) return;
  // Counted where they are rarer: cells written are those queued and those lit to 1, and blocks read
  // are those written and those that let in too little light to brighten.
  const std::size_t queued = increase_.size();
  std::uint64_t ones = 0, dimmer = 0, shapedReads = 0;
  Cursor own(frame_.queuedRef(LightFrame::refIndex(increase_[0].pos)));
  for (std::size_t head = 0; head < increase_.size(); ++head) {
    const LightEngine::Entry e = increase_[head];
    SectionRef& r = frame_.queuedRef(LightFrame::refIndex(e.pos));
    if (!r.levels) continue;  // not loaded
    if (&r != own.ref) {
      own.flush();
      own = Cursor(r);
    }
    const CellIndex index = LightFrame::local(e.pos);
    if (own.light(index) != e.level) continue;  // superseded since it was queued
    unsigned directions = e.directions;
    std::uint8_t inSection = kInSection[static_cast<std::size_t>(index)];
    const std::uint8_t* from = nullptr;  // the cell's parts of its sides, where it is shaped
    if (*own.shaped != 0) [[unlikely]] {
      // A section with shaped blocks: light does not leave a cell through a side covered whole.
      ++shapedReads;
      const BlockId self = own.block(index);
      if (attenuation_[self] & kShaped) {
        from = &faces_.faces[self * 6u];
        directions &= ~static_cast<unsigned>(faces_.full[self]);
        inSection &= static_cast<std::uint8_t>(~kInterior);
      }
    }
    LightEngine::Entry* out = increase_.room(6);
    std::size_t count = 0;
    const int throughAir = e.level - 1;  // the most a neighbour can get
    forNeighbours(
        r, own, index, e.pos, inSection, directions, [&](Cursor& c, CellIndex i, std::uint32_t pos, int d) {
          const std::uint8_t current = c.light(i);
          if (current >= throughAir) return;  // no block read: not even air would let it brighten
          const BlockId block = c.block(i);
          int attenuation = attenuation_[block];
          if ((attenuation & kShaped) || from) [[unlikely]] {
            // Nor across a side the two cells' parts cover together.
            const std::uint8_t to =
                attenuation & kShaped ? faces_.faces[block * 6u + static_cast<unsigned>(opposite(d))] : 0;
            if (faces_.blocks(from ? from[d] : 0, to)) {
              ++dimmer;
              return;
            }
            attenuation &= ~kShaped;
          }
          const int level = e.level - attenuation;
          if (level <= current) {
            ++dimmer;
            return;
          }
          c.set(frame_, i, static_cast<std::uint8_t>(level));
          if (level > 1)
            out[count++] = {pos, static_cast<std::uint8_t>(level), allBut(opposite(d))};
          else
            ++ones;
        });
    increase_.commit(count);
  }
  own.flush();
  const std::uint64_t writes = increase_.size() - queued + ones;
  blockReads_ += writes + dimmer + shapedReads;
  lightWrites_ += writes;
}

}  // namespace terrasol::light
