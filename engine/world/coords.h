#pragma once
// Integer world coordinates. Blocks are int32 on every axis: the world border at ±30 000 000 fits
// with room to spare, and chunk coordinates are exact (no floating point anywhere in addressing).

#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace terrasol {

inline constexpr int kChunkSize = 16;             // blocks per chunk and per section along each axis
inline constexpr int kChunkShift = 4;             // block >> kChunkShift is its chunk (or section)
inline constexpr int kLastCell = kChunkSize - 1;  // the last local coordinate, and the mask that gives it
inline constexpr int kChunkArea = kChunkSize * kChunkSize;  // columns per chunk, cells per section layer
static_assert(kChunkSize == 1 << kChunkShift);
inline constexpr int kMinY = -64;  // lowest block (inclusive)
inline constexpr int kMaxY = 320;  // one above the highest block
inline constexpr int kSectionCount = (kMaxY - kMinY) / kChunkSize;
inline constexpr int kWorldBorder = 30'000'000;
static_assert(kSectionCount == 24);
static_assert((kMaxY - kMinY) % kChunkSize == 0);

// Floor division by kChunkSize for negative values too (-1 -> chunk -1, local 15).
constexpr int chunkOf(int block) {
  return block >> kChunkShift;
}
constexpr int localOf(int block) {
  return block & kLastCell;
}
// A chunk's column (x, z local), numbered z * kChunkSize + x: the order of every per-column array.
constexpr int columnIndex(int x, int z) {
  return z * kChunkSize + x;
}

struct BlockPos {
  int x = 0, y = 0, z = 0;
  friend constexpr auto operator<=>(const BlockPos&, const BlockPos&) = default;
  constexpr BlockPos offset(int dx, int dy, int dz) const { return {x + dx, y + dy, z + dz}; }
  // The cell a point lies in (the callers' points are finite and within the world border).
  static BlockPos containing(double px, double py, double pz) {
    return {static_cast<int>(std::floor(px)), static_cast<int>(std::floor(py)),
            static_cast<int>(std::floor(pz))};
  }
};

struct ChunkPos {
  int x = 0, z = 0;
  friend constexpr auto operator<=>(const ChunkPos&, const ChunkPos&) = default;
  static constexpr ChunkPos of(const BlockPos& p) { return {chunkOf(p.x), chunkOf(p.z)}; }
  constexpr int minBlockX() const { return x * kChunkSize; }
  constexpr int minBlockZ() const { return z * kChunkSize; }
};

// The y of section `section`'s bottom layer.
constexpr int sectionMinY(int section) {
  return kMinY + section * kChunkSize;
}

// A section by chunk coordinates and section index (0 = the bottom section, y -64..-49).
struct SectionPos {
  int x = 0, section = 0, z = 0;
  friend constexpr auto operator<=>(const SectionPos&, const SectionPos&) = default;
  constexpr int minBlockY() const { return sectionMinY(section); }
};

constexpr bool inWorldHeight(int y) {
  return y >= kMinY && y < kMaxY;
}
constexpr int sectionOf(int y) {
  return (y - kMinY) >> kChunkShift;
}  // valid for y in world height

// The six face directions, in the order neighbours and faces are numbered everywhere.
enum class Direction : std::uint8_t { West, East, Down, Up, North, South };  // -x +x -y +y -z +z
inline constexpr BlockPos kDirectionOffsets[6] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                                  {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
// The neighbour's side that touches side `d`: west and east, down and up, north and south.
constexpr Direction opposite(Direction d) {
  return static_cast<Direction>(static_cast<int>(d) ^ 1);
}

}  // namespace terrasol

template <>
struct std::hash<terrasol::ChunkPos> {
  std::size_t operator()(const terrasol::ChunkPos& p) const noexcept {
    const auto key =
        (static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.x)) << 32) | static_cast<std::uint32_t>(p.z);
    return static_cast<std::size_t>(key * 0x9E3779B97F4A7C15ull);  // Fibonacci hashing mixes both halves
  }
};
