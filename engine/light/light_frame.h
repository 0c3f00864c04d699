#pragma once
// The block of the world one light update can touch, addressed without hashing: chunks around the
// update's seeds (an update reaches at most 30 blocks from them: 15 steps of removal, then 15 of
// refill, so +-2 chunks), with every cell named by one packed 32-bit frame position
//   x (0..255) | z (0..255) << 8 | y - kMinY (0..383) << 16
// and every section by a SectionRef holding raw pointers to its light and blocks. Internal to
// engine/light.

#include <array>
#include <cstdint>
#include <vector>

#include "light/light_engine.h"

namespace terrasol::light {

inline constexpr int kMaxFrameChunks = 16;  // x and z get 8 bits each

struct SectionRef {
  NibbleArray* layer = nullptr;         // null: the chunk is not loaded (acts opaque)
  const std::uint8_t* light = nullptr;  // layer->bytes()
  std::uint8_t* write = nullptr;        // layer->writableBytes() once written, null before
  const BlockId* blocks = nullptr;      // blocks[index & blockMask]: the dense array, or &uniform
  int blockMask = 0;
  BlockId uniform = kAir;
  std::uint8_t marks = 0;  // kFaceMarks of the cells written: whose halos changed
  const std::int16_t* skyTop = nullptr;  // the chunk's heightmap
};

// Per Section::index: bit d set when the cell lies on the section's face in Direction d, bit 7 always.
inline const std::array<std::uint8_t, Section::kVolume> kFaceMarks = [] {
  std::array<std::uint8_t, Section::kVolume> marks{};
  for (int i = 0; i < Section::kVolume; ++i) {
    const int x = i & 15, y = i >> 8, z = (i >> 4) & 15;
    marks[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(
        0x80 | (x == 0) | (x == 15) << 1 | (y == 0) << 2 | (y == 15) << 3 | (z == 0) << 4 | (z == 15) << 5);
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
    const int fx = x - minX_ * 16, fz = z - minZ_ * 16, fy = y - kMinY;
    if (static_cast<unsigned>(fx) >= static_cast<unsigned>(width_ * 16) ||
        static_cast<unsigned>(fz) >= static_cast<unsigned>(depth_ * 16) ||
        static_cast<unsigned>(fy) >= static_cast<unsigned>(kMaxY - kMinY)) {
      return false;
    }
    pos = static_cast<std::uint32_t>(fx | fz << 8 | fy << 16);
    return true;
  }
  int worldX(std::uint32_t pos) const { return static_cast<int>(pos & 255) + minX_ * 16; }
  int worldZ(std::uint32_t pos) const { return static_cast<int>((pos >> 8) & 255) + minZ_ * 16; }
  static int worldY(std::uint32_t pos) { return static_cast<int>(pos >> 16) + kMinY; }

  // Index of the section holding `pos`, and the cell's Section::index inside it.
  int refIndex(std::uint32_t pos) const {
    return ((static_cast<int>((pos >> 12) & 15) * width_) + static_cast<int>((pos >> 4) & 15)) * kSectionCount +
           static_cast<int>(pos >> 20);
  }
  static int local(std::uint32_t pos) {
    return static_cast<int>(((pos >> 8) & 0xF00) | ((pos >> 4) & 0xF0) | (pos & 15));
  }
  SectionRef& ref(int index) {
    const int chunk = index / kSectionCount;
    if (!resolved_[static_cast<std::size_t>(chunk)]) resolve(chunk);
    return refs_[static_cast<std::size_t>(index)];
  }
  // Chunk indices (z * width + x) resolved so far, and their sections' refs.
  const std::vector<int>& resolvedChunks() const { return resolvedList_; }
  SectionRef* chunkRefs(int chunk) { return &refs_[static_cast<std::size_t>(chunk * kSectionCount)]; }

  // Bit d set: the neighbour in Direction d is inside the frame.
  std::uint8_t insideMask(std::uint32_t pos) const {
    const unsigned fx = pos & 255, fz = (pos >> 8) & 255, fy = pos >> 16;
    return static_cast<std::uint8_t>((fx != 0) | (fx + 1 != static_cast<unsigned>(width_ * 16)) << 1 | (fy != 0) << 2 |
                                     (fy + 1 != static_cast<unsigned>(kMaxY - kMinY)) << 3 | (fz != 0) << 4 |
                                     (fz + 1 != static_cast<unsigned>(depth_ * 16)) << 5);
  }

  int minX() const { return minX_; }
  int minZ() const { return minZ_; }
  int width() const { return width_; }
  int depth() const { return depth_; }

 private:
  void resolve(int chunk);

  const ChunkWindow* window_ = nullptr;
  LightChannel channel_ = LightChannel::Block;
  int minX_ = 0, minZ_ = 0, width_ = 0, depth_ = 0;
  std::vector<SectionRef> refs_;
  std::vector<std::uint8_t> resolved_;
  std::vector<int> resolvedList_;
};

}  // namespace terrasol::light
