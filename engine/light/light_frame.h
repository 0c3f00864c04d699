#pragma once
// The block of the world one light update can touch, addressed without hashing: chunks around the
// update's seeds (an update reaches at most 30 blocks from them: 15 steps of removal, then 15 of
// refill, so +-2 chunks). Every section gets a SectionRef with raw pointers to its light and blocks,
// and every cell one packed 32-bit frame position
//   Section::index (12 bits) | ref index << 12
// so a step inside a section adds the index step, a step across a face adds a per-frame constant,
// and neither needs a bounds check: the refs form a grid with a ring of chunks and a section above
// and below the world that are never loaded, so every step out of the frame lands on an empty ref.
//
// An update works in plain bytes, one level per cell: a section's nibbles are unpacked into a slab
// the first time the update touches it, and the slabs it wrote are packed back when it ends (a
// section back to one level throughout keeps no bytes). A level read or written is then one byte,
// with no shifts and masks. A section of one level is only read at first, from a shared slab of that
// level, and gets its own on its first write: the ground under a torch is read for its light, never
// written, and costs no 4 KiB fill.
// Internal to engine/light.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "light/level_words.h"
#include "light/light_engine.h"

namespace terrasol::light {

inline constexpr int kMaxFrameChunks = 16;  // a side; with the ring, ref indices stay far below 2^20
inline constexpr int kRefSections = kSectionCount + 2;  // sections per chunk, with the empty ones
inline constexpr int kIndexBits = 12;                   // a frame position's low bits: the Section::index
static_assert(1 << kIndexBits == Section::kVolume);
static_assert((kMaxFrameChunks + 2) * (kMaxFrameChunks + 2) * kRefSections < (1 << (32 - kIndexBits)),
              "a frame position keeps its ref index in the bits above the cell index");

// A level in an update's slab. An enum, not std::uint8_t: a store through unsigned char may alias
// anything, so the compiler would reload every pointer and counter after each level written.
enum class Level : std::uint8_t {};

struct SectionRef {
  NibbleArray* layer = nullptr;  // null: not loaded, or outside the world (acts opaque)
  Level* levels = nullptr;       // the slab, by Section::index; null until the section is touched
  bool shared = false;           // levels is a read-only slab of the layer's one level (see own())
  unsigned marks = 0;            // kWriteMarks of the cells written: what to pack back, whose halos changed
  const BlockId* blocks = nullptr;  // blocks[index & blockMask]: the dense array, or &uniform
  int blockMask = 0;
  BlockId uniform = kAir;
  const std::uint16_t* emitters = nullptr;  // the section's count in ChunkLight::emitters: at 0 no cell emits
  const std::uint16_t* shaped = nullptr;    // and in ChunkLight::shaped: at 0 no cell has light sides
  const std::int16_t* skyTop = nullptr;     // the chunk's heightmap
  int minY = 0;                             // world y of the section's bottom layer
  std::uint32_t update = 0;                 // the frame's update count when it was resolved

  // The slab as bytes, for whole-section copies and comparisons.
  std::uint8_t* levelBytes() { return reinterpret_cast<std::uint8_t*>(levels); }
};

// What writing a cell marks, per Section::index: bit d when the cell lies on the section's face in
// Direction d (the halo of the section beyond changed), and its band of layers (level_words.h).
inline const std::array<std::uint8_t, Section::kVolume> kWriteMarks = [] {
  std::array<std::uint8_t, Section::kVolume> marks{};
  for (int i = 0; i < Section::kVolume; ++i) {
    const int x = Section::xOf(i), y = Section::yOf(i), z = Section::zOf(i);
    marks[static_cast<std::size_t>(i)] =
        static_cast<std::uint8_t>(bandMark(y / kLayersPerBand) | sectionFaces(x, y, z));
  }
  return marks;
}();

// The chunks of a frame, looked up once per update and shared by both channels' frames.
struct ChunkWindow {
  // Chunks from min to max inclusive; `excluded` (a chunk being unloaded) and unlit chunks are null.
  ChunkWindow(World& world, ChunkPos min, ChunkPos max, const Chunk* excluded = nullptr);
  ChunkPos min;
  int width, depth;
  std::vector<Chunk*> chunks;  // z * width + x
};

class LightFrame {
 public:
  // Sections reference the `channel`'s light; they are filled in per chunk on first use. Reset for
  // each update, so the arrays are allocated once.
  void reset(const ChunkWindow& window, LightChannel channel);

  // Frame position of a world cell; false outside the frame or the world height.
  bool toFrame(int x, int y, int z, std::uint32_t& pos) const {
    const int fx = x - minX_ * kChunkSize, fz = z - minZ_ * kChunkSize, fy = y - kMinY;
    if (static_cast<unsigned>(fx) >= static_cast<unsigned>(width_ * kChunkSize) ||
        static_cast<unsigned>(fz) >= static_cast<unsigned>(depth_ * kChunkSize) ||
        static_cast<unsigned>(fy) >= static_cast<unsigned>(kMaxY - kMinY)) {
      return false;
    }
    const int ref = (((fz >> kChunkShift) + 1) * stride_ + (fx >> kChunkShift) + 1) * kRefSections +
                    (fy >> kChunkShift) + 1;
    pos = static_cast<std::uint32_t>(ref << kIndexBits |
                                     Section::index(fx & kLastCell, fy & kLastCell, fz & kLastCell));
    return true;
  }
  static int refIndex(std::uint32_t pos) { return static_cast<int>(pos >> kIndexBits); }
  static int local(std::uint32_t pos) { return static_cast<int>(pos & (Section::kVolume - 1)); }
  // The position one step across the section's face in Direction d.
  std::uint32_t across(std::uint32_t pos, int d) const {
    return pos + static_cast<std::uint32_t>(across_[d]);
  }

  // The section's ref, its levels unpacked if it is loaded.
  SectionRef& ref(int index) {
    SectionRef& r = packedRef(index);
    if (!r.levels && r.layer) unpack(r);
    return r;
  }
  // Gives a section read from a shared slab one of its own, to write; returns its levels.
  Level* own(SectionRef& r) {
    if (r.shared) [[unlikely]]
      unshare(r);
    return r.levels;
  }
  // The section's ref, its levels left packed: its layer is read as it is.
  SectionRef& packedRef(int index) {
    SectionRef& r = refs_[static_cast<std::size_t>(index)];
    if (r.update != update_) resolve(index / kRefSections);
    return r;
  }
  // The ref of a position that was queued: its section was resolved and unpacked then.
  SectionRef& queuedRef(int index) { return refs_[static_cast<std::size_t>(index)]; }
  // Packs a written section's levels back into its layer, which keeps no bytes if they are all one
  // level; returns and clears its marks.
  unsigned pack(SectionRef& r);
  // Grid chunk indices resolved so far, their sections' refs (kRefSections each, the first and last
  // empty), and their chunk positions.
  const std::vector<int>& resolvedChunks() const { return resolvedList_; }
  SectionRef* chunkRefs(int chunk) { return &refs_[static_cast<std::size_t>(chunk * kRefSections)]; }
  ChunkPos chunkPos(int chunk) const { return {minX_ + chunk % stride_ - 1, minZ_ + chunk / stride_ - 1}; }

 private:
  void resolve(int chunk);
  void unpack(SectionRef& r);
  void unshare(SectionRef& r);
  Level* takeSlab();

  const ChunkWindow* window_ = nullptr;
  LightChannel channel_ = LightChannel::Block;
  int minX_ = 0, minZ_ = 0, width_ = 0, depth_ = 0;
  int stride_ = 0;  // grid chunks per row: width_ + 2
  std::int32_t across_[6] = {};
  std::vector<SectionRef> refs_;
  std::uint32_t update_ = 0;  // counts resets: refs stamped with an older count are not resolved yet
  std::vector<int> resolvedList_;
  using Slab = std::array<Level, Section::kVolume>;
  std::vector<std::unique_ptr<Slab>> slabs_;  // kept between updates
  std::size_t slabsUsed_ = 0;
  std::array<std::unique_ptr<Slab>, kLightLevels> levelSlabs_;   // read-only, one a level, made on first use
  static constexpr std::size_t kMaxSpareBytes = 64;              // 128 KiB
  std::vector<std::unique_ptr<NibbleArray::Bytes>> spareBytes_;  // layers' bytes freed by pack(), for reuse
};

}  // namespace terrasol::light
