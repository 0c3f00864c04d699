#pragma once
// A section's light levels compared sixteen at a time: NibbleArray bytes read as 64-bit words, so
// word w holds the cells 16w..16w+15 (one x row), cell 16w+k in bits 4k..4k+3. The results are masks
// with bit 4k set for cell k of the word. Internal to engine/light.

#include <array>
#include <cstdint>
#include <cstring>

namespace terrasol::light {

inline constexpr int kNibbleWords = 256;  // per section
inline constexpr std::uint64_t kNibbleLowBits = 0x1111111111111111;

inline std::uint64_t nibbleWord(const std::uint8_t* bytes, int word) {
  std::uint64_t w;
  std::memcpy(&w, bytes + 8 * word, sizeof w);
  return w;
}

// Cells whose levels differ between two words.
constexpr std::uint64_t changedNibbles(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t x = a ^ b;
  return (x | x >> 1 | x >> 2 | x >> 3) & kNibbleLowBits;
}

// Cells whose level in `after` is lower than in `before`. Even and odd cells are compared in separate
// 8-bit lanes, where (before | 16) - (after + 1) keeps bit 4 exactly when before > after, and no lane
// borrows from the next.
constexpr std::uint64_t lowerNibbles(std::uint64_t before, std::uint64_t after) {
  constexpr std::uint64_t kLow = 0x0F0F0F0F0F0F0F0F, kOnes = 0x0101010101010101, kBit4 = 0x1010101010101010;
  auto lanes = [&](std::uint64_t b, std::uint64_t a) { return (((b | kBit4) - (a + kOnes)) & kBit4) >> 4; };
  return lanes(before & kLow, after & kLow) | lanes(before >> 4 & kLow, after >> 4 & kLow) << 4;
}
static_assert(lowerNibbles(0xF0, 0x0F) == 0x10 && lowerNibbles(0x00, 0xFF) == 0 && lowerNibbles(0x1, 0x0) == 0x1);

// Per word, the cells on a face of the section: the first and last of every row (x = 0 and 15), and
// every cell of the rows at y or z = 0 or 15.
inline constexpr std::array<std::uint64_t, kNibbleWords> kFaceNibbles = [] {
  std::array<std::uint64_t, kNibbleWords> masks{};
  for (int w = 0; w < kNibbleWords; ++w) {
    const int y = w >> 4, z = w & 15;
    masks[static_cast<std::size_t>(w)] =
        y == 0 || y == 15 || z == 0 || z == 15 ? kNibbleLowBits : std::uint64_t{1} | std::uint64_t{1} << 60;
  }
  return masks;
}();

}  // namespace terrasol::light
