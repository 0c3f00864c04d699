#pragma once
// A section's light levels moved between NibbleArray bytes (two levels a byte) and plain bytes (one
// level a byte, what updates work in), and plain bytes compared eight at a time: word q holds the
// cells 8q..8q+7, cell 8q+k in bits 8k..8k+7. Internal to engine/light.

#include <cstdint>
#include <cstring>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "core/light_level.h"
#include "light/face_bits.h"
#include "world/nibble_array.h"

namespace terrasol::light {

// Written cells mark their band of layers, the section's lower or upper half (bit 6 or 7 of a
// SectionRef's marks): packing skips a band nobody wrote. Two bands keep the marks in a byte per cell
// (kWriteMarks); with eight bands in 16 bits the larger table cost a torch's update more time in
// cache misses (15.3 against 15.0 us) than the finer packing saved.
inline constexpr int kLayersPerBand = 8;
inline constexpr int kBands = kChunkSize / kLayersPerBand;
inline constexpr int kBandNibbleBytes = NibbleArray::kBytes / kBands;
constexpr unsigned bandMark(int band) {
  return 0x40u << band;
}

// Word q of a section's plain bytes.
inline std::uint64_t byteWord(const std::uint8_t* bytes, int q) {
  std::uint64_t w;
  std::memcpy(&w, bytes + 8 * q, sizeof w);
  return w;
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
  const int row = q >> 1, y = row >> kChunkShift, z = row & kLastCell;
  if (y == 0 || y == kLastCell || z == 0 || z == kLastCell) return kByteHighBits;
  return q & 1 ? std::uint64_t{0x80} << 56 : 0x80;
}

// The kWriteMarks bits (light_frame.h) of the cells `changed` marks in byte word q.
constexpr unsigned writeMarksOfBytes(int q, std::uint64_t changed) {
  if (changed == 0) return 0;
  const int row = q >> 1, y = row >> kChunkShift, z = row & kLastCell;
  const bool west = !(q & 1) && (changed & 0x80), east = (q & 1) && (changed >> 63);
  return bandMark(y / kLayersPerBand) | west * kWestFace | east * kEastFace | (y == 0) * kDownFace |
         (y == kLastCell) * kUpFace | (z == 0) * kNorthFace | (z == kLastCell) * kSouthFace;
}

// Levels (4096, one a byte) from NibbleArray bytes, and back. SSE2 where there is SSE2 (every x86-64);
// the plain loops elsewhere.
inline void unpackNibbles(const std::uint8_t* nibbles, std::uint8_t* levels) {
#ifdef __SSE2__
  const __m128i low = _mm_set1_epi8(kLightMask);
  for (int i = 0; i < NibbleArray::kBytes; i += 16) {
    const __m128i n = _mm_loadu_si128(reinterpret_cast<const __m128i*>(nibbles + i));
    const __m128i even = _mm_and_si128(n, low), odd = _mm_and_si128(_mm_srli_epi16(n, 4), low);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(levels + 2 * i), _mm_unpacklo_epi8(even, odd));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(levels + 2 * i + 16), _mm_unpackhi_epi8(even, odd));
  }
#else
  for (int i = 0; i < NibbleArray::kBytes; ++i) {
    levels[2 * i] = nibbles[i] & kLightMask;
    levels[2 * i + 1] = static_cast<std::uint8_t>(nibbles[i] >> 4);
  }
#endif
}
// Packs the levels of nibble bytes [begin, end) (levels 2 * begin .. 2 * end); returns the level they
// all share, or -1 when they differ: a uniform section need not keep its bytes.
inline int packNibbles(const std::uint8_t* levels, std::uint8_t* nibbles, int begin = 0,
                       int end = NibbleArray::kBytes) {
#ifdef __SSE2__
  // Each 16-bit lane holds an even level in its low byte and the odd one in its high byte.
  const __m128i lowByte = _mm_set1_epi16(0xFF);
  auto pairs = [&](const std::uint8_t* at) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
    return _mm_and_si128(_mm_or_si128(v, _mm_srli_epi16(v, 4)), lowByte);
  };
  // Every byte position's OR and AND over all the bytes written: equal, and one byte throughout, only
  // when every byte is the same.
  __m128i any = _mm_setzero_si128(), all = _mm_set1_epi8(-1);
  for (int i = begin; i < end; i += 16) {
    const __m128i packed = _mm_packus_epi16(pairs(levels + 2 * i), pairs(levels + 2 * i + 16));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(nibbles + i), packed);
    any = _mm_or_si128(any, packed);
    all = _mm_and_si128(all, packed);
  }
  const __m128i first = _mm_set1_epi8(static_cast<char>(nibbles[begin]));
  const bool sameBytes = _mm_movemask_epi8(_mm_cmpeq_epi8(any, all)) == 0xFFFF &&
                         _mm_movemask_epi8(_mm_cmpeq_epi8(any, first)) == 0xFFFF;
#else
  std::uint8_t any = 0, all = 0xFF;
  for (int i = begin; i < end; ++i) {
    nibbles[i] = static_cast<std::uint8_t>(levels[2 * i] | levels[2 * i + 1] << 4);
    any |= nibbles[i];
    all &= nibbles[i];
  }
  const bool sameBytes = any == all;
#endif
  const int low = nibbles[begin] & kLightMask;
  return sameBytes && nibbles[begin] >> 4 == low ? low : -1;
}

// True when nibble bytes [begin, end) all hold the level `level` (in both nibbles).
inline bool nibblesAre(const std::uint8_t* nibbles, int begin, int end, int level) {
  const auto byte = static_cast<std::uint8_t>(level * 0x11);
#ifdef __SSE2__
  const __m128i want = _mm_set1_epi8(static_cast<char>(byte));
  __m128i differ = _mm_setzero_si128();
  for (int i = begin; i < end; i += 16)
    differ = _mm_or_si128(
        differ, _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(nibbles + i)), want));
  return _mm_movemask_epi8(_mm_cmpeq_epi8(differ, _mm_setzero_si128())) == 0xFFFF;
#else
  for (int i = begin; i < end; ++i)
    if (nibbles[i] != byte) return false;
  return true;
#endif
}

}  // namespace terrasol::light
