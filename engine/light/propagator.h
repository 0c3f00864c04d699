#pragma once
// The flood fill shared by every light update: one channel, a decrease queue, then an increase queue.
// Internal to engine/light.

#include <algorithm>
#include <array>
#include <vector>

#include "core/assert.h"
#include "light/changed_sections.h"
#include "light/light_faces.h"
#include "light/light_frame.h"

namespace terrasol::light {

inline constexpr std::uint8_t kAllDirections = kAllFaces;
constexpr std::uint8_t allBut(int direction) {
  return static_cast<std::uint8_t>(kAllDirections & ~faceBit(direction));
}
constexpr int opposite(int direction) {
  return direction ^ 1;
}  // West<->East, Down<->Up, North<->South

// What light loses entering a block: max(1, opacity), tabled per block id so the flood fill reads it
// with one load.
inline std::vector<std::uint8_t> attenuations(const std::vector<std::uint8_t>& opacities) {
  std::vector<std::uint8_t> a(opacities);
  for (std::uint8_t& v : a) v = std::max<std::uint8_t>(1, v);
  return a;
}

// The flood fill's table: attenuations() with kShaped set where the block's shape takes part in
// light (LightFaces): light entering or leaving such a cell checks the side it crosses.
inline constexpr std::uint8_t kShaped = 0x80;
inline std::vector<std::uint8_t> floodAttenuations(const std::vector<std::uint8_t>& attenuation,
                                                   const LightFaces& faces) {
  std::vector<std::uint8_t> a(attenuation);
  for (std::size_t b = 0; b < a.size(); ++b) a[b] |= faces.shaped(static_cast<BlockId>(b)) ? kShaped : 0;
  return a;
}

// Sky light of a cell in the top layer of the world that is not open sky: lit from above, through
// its own block (`attenuation`: see attenuations()).
constexpr std::uint8_t topLayerSky(std::uint8_t attenuation) {
  return static_cast<std::uint8_t>(kMaxLight - attenuation);
}

// Steps per Direction of Section::index within a section, and so of a frame position there.
inline constexpr int kIndexStep[6] = {-1, 1, -kChunkArea, kChunkArea, -kChunkSize, kChunkSize};

// Per Section::index: bit d set when the neighbour in Direction d is in the same section; kInterior
// when the cell is on no face of the section.
inline constexpr std::uint8_t kInterior = 0x40;
inline const std::array<std::uint8_t, Section::kVolume> kInSection = [] {
  std::array<std::uint8_t, Section::kVolume> masks{};
  for (int i = 0; i < Section::kVolume; ++i) {
    const unsigned m = kAllFaces & ~sectionFaces(Section::xOf(i), Section::yOf(i), Section::zOf(i));
    masks[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(m | (m == kAllFaces) * kInterior);
  }
  return masks;
}();

// A queue over storage reused between updates. The hot loops reserve room for an entry's six
// neighbours once and write through a local pointer; the queue keeps a raw pointer and counts, which
// the compiler can hold in registers, where a vector's would be reloaded through the reference.
class EntryQueue {
 public:
  using Entry = LightEngine::Entry;
  explicit EntryQueue(std::vector<Entry>& storage) : storage_(storage) {
    if (storage_.size() < 1024) storage_.resize(1024);
    data_ = storage_.data();
    capacity_ = storage_.size();
  }
  std::size_t size() const { return size_; }
  const Entry& operator[](std::size_t i) const { return data_[i]; }
  void push(const Entry& e) {
    *room(1) = e;
    ++size_;
  }
  // Room for `n` entries at the end; commit(k) keeps the first k written there.
  Entry* room(std::size_t n) {
    if (size_ + n > capacity_) grow(n);
    return data_ + size_;
  }
  void commit(std::size_t k) { size_ += k; }

 private:
  void grow(std::size_t n) {
    storage_.resize(std::max(capacity_ * 2, size_ + n));
    data_ = storage_.data();
    capacity_ = storage_.size();
  }

  std::vector<Entry>& storage_;
  Entry* data_;
  std::size_t capacity_;
  std::size_t size_ = 0;
};

// A cell's Section::index in the flood fill's hot loops: pointer-sized, so that index +- step folds
// into the address of the load instead of costing a sign extension per neighbour.
using CellIndex = std::ptrdiff_t;

// A section's pointers copied into locals, which the compiler keeps in registers through a cell's
// visits (and the queue loops through consecutive entries in one section); flush() records the faces
// of the cells written. The one way the flood fill writes light.
struct Cursor {
  explicit Cursor(SectionRef& r)
      : ref(&r),
        levels(r.levels),
        blocks(r.blocks),
        mask(r.blockMask),
        skyTop(r.skyTop),
        minY(r.minY),
        emitters(r.emitters),
        shaped(r.shaped),
        shared(r.shared) {}
  void flush() { ref->marks |= marks; }
  std::uint8_t light(CellIndex i) const { return static_cast<std::uint8_t>(levels[i]); }
  BlockId block(CellIndex i) const { return blocks[i & mask]; }
  // `frame` gives a section read from a shared slab its own on its first write.
  void set(LightFrame& frame, CellIndex i, std::uint8_t level) {
    if (shared) [[unlikely]] {
      levels = frame.own(*ref);
      shared = false;
    }
    levels[i] = Level{level};
    marks |= kWriteMarks[static_cast<std::size_t>(i)];
  }

  SectionRef* ref;
  Level* levels;
  const BlockId* blocks;
  CellIndex mask;
  const std::int16_t* skyTop;
  int minY;
  const std::uint16_t* emitters;
  const std::uint16_t* shaped;
  bool shared;
  unsigned marks = 0;
};

// A cell of the frame: its section and its index there.
struct Cell {
  SectionRef* ref = nullptr;
  int index = 0;
  std::uint32_t pos = 0;
};

class Propagator {
 public:
  // Resets `frame` to the window and channel.
  // `attenuation` by block id: see floodAttenuations().
  Propagator(LightFrame& frame, const ChunkWindow& window, LightChannel channel,
             const std::uint8_t* attenuation, const LightFaces& faces, const std::uint8_t* emission,
             std::vector<LightEngine::Entry>& decrease, std::vector<LightEngine::Entry>& increase,
             LightStats& stats, ChangedSections& changed);
  ~Propagator();  // adds the counters to the engine's stats

  // False outside the frame or in a chunk that is not loaded.
  bool locate(int x, int y, int z, Cell& cell) {
    std::uint32_t pos;
    if (!frame_.toFrame(x, y, z, pos)) return false;
    return locate(pos, cell);
  }
  bool locate(std::uint32_t pos, Cell& cell) {
    cell = {&frame_.ref(frame_.refIndex(pos)), LightFrame::local(pos), pos};
    return cell.ref->layer != nullptr;
  }
  // Like locate, but the section's levels stay packed: for reading its layer before run() writes
  // anything, without the cost of unpacking.
  bool locatePacked(int x, int y, int z, Cell& cell) {
    std::uint32_t pos;
    if (!frame_.toFrame(x, y, z, pos)) return false;
    cell = {&frame_.packedRef(frame_.refIndex(pos)), LightFrame::local(pos), pos};
    return cell.ref->layer != nullptr;
  }
  static std::uint8_t light(const SectionRef& r, int index) {
    return static_cast<std::uint8_t>(r.levels[index]);
  }
  std::uint8_t light(const Cell& c) const { return light(*c.ref, c.index); }
  void setLight(const Cell& c, std::uint8_t level) { setLight(*c.ref, c.index, level); }
  // The level a cell has by itself: its emission (block light), or kMaxLight in the open sky column.
  std::uint8_t source(const Cell& c) { return source(*c.ref, c.index); }

  void decrease(int x, int y, int z, std::uint8_t level, std::uint8_t directions) {
    std::uint32_t pos;
    if (frame_.toFrame(x, y, z, pos)) decrease(pos, level, directions);
  }
  void increase(int x, int y, int z, std::uint8_t level, std::uint8_t directions) {
    std::uint32_t pos;
    if (frame_.toFrame(x, y, z, pos)) increase(pos, level, directions);
  }
  // The loops take a queued position's ref as it is (LightFrame::queuedRef): resolve it now. The loops
  // trust a seed's level (a byte) to be a light level: one above 15 would spread wrong light.
  void decrease(std::uint32_t pos, std::uint8_t level, std::uint8_t directions) {
    TERRASOL_ASSERT(level <= 15 && directions <= kAllDirections, "light: a decrease seeded out of range");
    frame_.ref(LightFrame::refIndex(pos));
    decrease_.push({pos, level, directions});
  }
  void increase(std::uint32_t pos, std::uint8_t level, std::uint8_t directions) {
    TERRASOL_ASSERT(level <= 15 && directions <= kAllDirections, "light: an increase seeded out of range");
    frame_.ref(LightFrame::refIndex(pos));
    increase_.push({pos, level, directions});
  }
  void setLight(SectionRef& r, int index, std::uint8_t level) {
    frame_.own(r)[index] = Level{level};
    r.marks |= kWriteMarks[static_cast<std::size_t>(index)];
    ++lightWrites_;
  }
  std::uint8_t source(SectionRef& r, int index) { return source(Cursor(r), index, blockReads_); }
  std::uint8_t source(const Cursor& c, CellIndex index, std::uint64_t& reads) const {
    if (channel_ == LightChannel::Block) {
      if (*c.emitters == 0) return 0;  // no block to read: the section has no emitter
      ++reads;
      return emission_[c.block(index)];
    }
    const int y = c.minY + static_cast<int>(index >> Section::kYShift);
    if (y > c.skyTop[index & Section::kColumnMask]) return kMaxLight;
    // The top layer of the world is lit from the sky above it, through its own opacity.
    if (y == kMaxY - 1) {
      ++reads;
      return topLayerSky(attenuation_[c.block(index)] & ~kShaped);
    }
    return 0;
  }
  // Gives every cell of the section whose cell 0 is at `origin` the level in `levels` (4096 bytes, by
  // Section::index). A face cell that loses light starts a decrease outward with its old level: light that
  // left the section through it may have to go. Cells inside need none, they all have new levels.
  void replaceLevels(SectionRef& r, std::uint32_t origin, const std::uint8_t* levels);
  // Frame position of Section::index `index` in the section whose cell 0 is at `origin`.
  static std::uint32_t posOf(std::uint32_t origin, int index) {
    return origin + static_cast<std::uint32_t>(index);
  }

  // Runs the decrease queue, then the increase queue (which the decreases add to), to the end, and
  // writes the new levels back into the sections' layers.
  void run();

 private:
  // `own` is r's cursor, switched by the caller when its entries move to another section.
  template <class Visit>
  void forNeighbours(SectionRef& r, Cursor& own, CellIndex index, std::uint32_t pos, std::uint8_t inSection,
                     unsigned directions, Visit&& visit);
  void writeBack();
  void runDecrease();
  void runIncrease();

  LightFrame& frame_;
  LightChannel channel_;
  const std::uint8_t* attenuation_;
  const LightFaces& faces_;
  const std::uint8_t* emission_;
  EntryQueue decrease_;
  EntryQueue increase_;
  LightStats& stats_;
  std::uint64_t blockReads_ = 0, lightWrites_ = 0;
  ChangedSections& changed_;
};

}  // namespace terrasol::light
