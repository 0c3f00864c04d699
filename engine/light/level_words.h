#pragma once
// A section's light levels moved between NibbleArray bytes (two levels a byte) and plain bytes (one
// level a byte, what updates work in), and compared many at a time in 64-bit words:
// - NibbleArray bytes: word w holds the cells 16w..16w+15 (one x row at y = w / 16, z = w % 16), cell
//   16w+k in bits 4k..4k+3;
// - plain bytes: word q holds the cells 8q..8q+7, cell 8q+k in bits 8k..8k+7.
// Internal to engine/light.

#include <cstdint>
#include <cstring>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "world/nibble_array.h"

namespace terrasol::light {

inline constexpr int kNibbleWords = 256;  // per section

// Word w of either layout: 8 bytes.
inline std::uint64_t nibbleWord(const std::uint8_t* bytes, int word) {
  std::uint64_t w;
  std::memcpy(&w, bytes + 8 * word, sizeof w);
  return w;
}
inline std::uint64_t byteWord(const std::uint8_t* bytes, int word) { return nibbleWord(bytes, word); }

// The kFaceMarks bits of the cells whose levels differ between two sections' NibbleArray bytes, with
// bit 7 when any does: the bits of every word that differs, OR-ed together, show the x faces (cells 0
// and 15 of a row); the rows at y = 0 or 15 and at z = 0 or 15 are whole words.
inline std::uint8_t changedFaces(const std::uint8_t* a, const std::uint8_t* b) {
  std::uint64_t diff[kNibbleWords];
  std::uint64_t any = 0, down = 0, up = 0, north = 0, south = 0;
  for (int w = 0; w < kNibbleWords; ++w) any |= diff[w] = nibbleWord(a, w) ^ nibbleWord(b, w);
  if (any == 0) return 0;
  for (int k = 0; k < 16; ++k) {
    down |= diff[k];
    up |= diff[240 + k];
    north |= diff[16 * k];
    south |= diff[16 * k + 15];
  }
  return static_cast<std::uint8_t>(0x80 | ((any & 15) != 0) | ((any >> 60) != 0) << 1 | (down != 0) << 2 |
                                   (up != 0) << 3 | (north != 0) << 4 | (south != 0) << 5);
}

inline constexpr int kByteWords = 512;  // per section
inline constexpr std::uint64_t kByteHighBits = 0x8080808080808080;

// Cells whose levels (0..15, a byte each) differ: bit 8k+7 set for cell k.
constexpr std::uint64_t changedBytes(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t x = a ^ b;
  return (((x & ~kByteHighBits) + ~kByteHighBits) | x) & kByteHighBits;
}
// Cells whose level in `after` is lower than in `before`: (before | 128) - (after + 1) keeps bit 7
// exactly when before > after, and no byte borrows from the next.
constexpr std::uint64_t lowerBytes(std::uint64_t before, std::uint64_t after) {
  return ((before | kByteHighBits) - (after + 0x0101010101010101)) & kByteHighBits;
}
static_assert(lowerBytes(0x0F00, 0x0E0F) == 0x8000 && changedBytes(0x0F00, 0x0E0F) == 0x8080 &&
              changedBytes(7, 7) == 0);
// The cells of byte word q on a face of the section (bit 7 of their bytes): the whole row at y or z =
// 0 or 15, else its first cell (x = 0) or last (x = 15).
constexpr std::uint64_t faceBytes(int q) {
  const int row = q >> 1, y = row >> 4, z = row & 15;
  if (y == 0 || y == 15 || z == 0 || z == 15) return kByteHighBits;
  return q & 1 ? std::uint64_t{0x80} << 56 : 0x80;
}

// Levels (4096, one a byte) from NibbleArray bytes, and back. SSE2 where there is SSE2 (every x86-64);
// the plain loops elsewhere.
inline void unpackNibbles(const std::uint8_t* nibbles, std::uint8_t* levels) {
#ifdef __SSE2__
  const __m128i low = _mm_set1_epi8(15);
  for (int i = 0; i < NibbleArray::kBytes; i += 16) {
    const __m128i n = _mm_loadu_si128(reinterpret_cast<const __m128i*>(nibbles + i));
    const __m128i even = _mm_and_si128(n, low), odd = _mm_and_si128(_mm_srli_epi16(n, 4), low);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(levels + 2 * i), _mm_unpacklo_epi8(even, odd));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(levels + 2 * i + 16), _mm_unpackhi_epi8(even, odd));
  }
#else
  for (int i = 0; i < NibbleArray::kBytes; ++i) {
    levels[2 * i] = nibbles[i] & 15;
    levels[2 * i + 1] = static_cast<std::uint8_t>(nibbles[i] >> 4);
  }
#endif
}
inline void packNibbles(const std::uint8_t* levels, std::uint8_t* nibbles) {
#ifdef __SSE2__
  // Each 16-bit lane holds an even level in its low byte and the odd one in its high byte.
  const __m128i lowByte = _mm_set1_epi16(0xFF);
  auto pairs = [&](const std::uint8_t* at) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
    return _mm_and_si128(_mm_or_si128(v, _mm_srli_epi16(v, 4)), lowByte);
  };
  for (int i = 0; i < NibbleArray::kBytes; i += 16) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(nibbles + i),
                     _mm_packus_epi16(pairs(levels + 2 * i), pairs(levels + 2 * i + 16)));
  }
#else
  for (int i = 0; i < NibbleArray::kBytes; ++i) {
    nibbles[i] = static_cast<std::uint8_t>(levels[2 * i] | levels[2 * i + 1] << 4);
  }
#endif
}

}  // namespace terrasol::light
