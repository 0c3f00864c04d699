#pragma once
// A 16x16x16 cube of blocks.
//
// Layout: blocks are BlockIds (uint16) in one dense array of 4096, index = (y * 16 + z) * 16 + x with
// x, z, y local to the section (0..15): x varies fastest, so a row along x is contiguous and a
// horizontal 16x16 layer is one 512-byte run. A uniform section (all one block, typically all air or
// all stone) stores no array at all: `blocks_` is null and `uniform_` holds the block. Writing a
// different block into a uniform section allocates the array (8 KiB); compact() frees it again when
// the section has become uniform.

#include <array>
#include <memory>

#include "world/block.h"
#include "world/coords.h"

namespace terrasol {

class Section {
 public:
  static constexpr int kVolume = kChunkSize * kChunkSize * kChunkSize;
  static constexpr int index(int x, int y, int z) { return (y * kChunkSize + z) * kChunkSize + x; }
  static constexpr int kYShift = 2 * kChunkShift;     // index >> kYShift: the cell's y
  static constexpr int kColumnMask = kChunkArea - 1;  // index & kColumnMask: its column (columnIndex)
  // Local coordinates of an index.
  static constexpr int xOf(int index) { return index & kLastCell; }
  static constexpr int yOf(int index) { return index >> kYShift; }
  static constexpr int zOf(int index) { return (index >> kChunkShift) & kLastCell; }
  using Blocks = std::array<BlockId, kVolume>;
  static_assert(sizeof(Blocks) == 8192);

  explicit Section(BlockId fill = kAir) : uniform_(fill) {}
  Section(const Section& other);
  Section& operator=(const Section& other);
  Section(Section&&) noexcept = default;
  Section& operator=(Section&&) noexcept = default;

  BlockId get(int x, int y, int z) const { return blocks_ ? (*blocks_)[index(x, y, z)] : uniform_; }
  BlockId at(int index) const { return blocks_ ? (*blocks_)[static_cast<std::size_t>(index)] : uniform_; }
  // Returns the block that was there.
  BlockId set(int x, int y, int z, BlockId id);
  void fill(BlockId id) {
    blocks_.reset();
    uniform_ = id;
  }

  bool isUniform() const { return !blocks_; }
  // The block of a uniform section; meaningless otherwise.
  BlockId uniformBlock() const { return uniform_; }
  bool isAllAir() const { return !blocks_ && uniform_ == kAir; }
  // The dense array, or null for a uniform section.
  const Blocks* blocks() const { return blocks_.get(); }
  Blocks& mutableBlocks();  // allocates (filled with the uniform block) when uniform

  // Drops the array when every block is the same. Returns true when the section is uniform after.
  bool compact();
  std::size_t memoryBytes() const { return blocks_ ? sizeof(Blocks) : 0; }

 private:
  std::unique_ptr<Blocks> blocks_;
  BlockId uniform_ = kAir;
};

static_assert(Section::index(kLastCell, kLastCell, kLastCell) == Section::kVolume - 1);
static_assert(Section::index(1, 0, 0) == 1 && Section::index(0, 0, 1) == kChunkSize &&
              Section::index(0, 1, 0) == kChunkArea);
static_assert(Section::xOf(Section::index(3, 5, 7)) == 3 && Section::yOf(Section::index(3, 5, 7)) == 5 &&
              Section::zOf(Section::index(3, 5, 7)) == 7);

}  // namespace terrasol
