#include "mesh/section_snapshot.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace terrasol {
namespace {

// True when every cell of `section`'s layer facing direction `d` (the face it shows towards the
// section we are meshing) is an opaque cube. Uniform sections answer without looking at cells.
bool faceIsOpaque(const Section& section, const std::vector<std::uint8_t>& opaque, int d) {
  if (section.isUniform()) return opaque[section.uniformBlock()] != 0;
  for (int a = 0; a < kChunkSize; ++a)
    for (int b = 0; b < kChunkSize; ++b) {
      // The layer of `section` that touches ours: its opposite side in direction d.
      const int x = d == 0 ? kLastCell : d == 1 ? 0 : a;
      const int y = d == 2 ? kLastCell : d == 3 ? 0 : (d < 2 ? a : b);
      const int z = d == 4 ? kLastCell : d == 5 ? 0 : b;
      if (!opaque[section.get(x, y, z)]) return false;
    }
  return true;
}

bool buried(const World& world, const Chunk& chunk, SectionPos pos) {
  const std::vector<std::uint8_t>& opaque = world.opaqueCubes();
  for (int d = 0; d < 6; ++d) {
    const BlockPos& o = kDirectionOffsets[d];
    const int s = pos.section + o.y;
    if (s < 0) continue;                   // below the world: never seen
    if (s >= kSectionCount) return false;  // open to the sky above the world
    const Chunk* neighbour = o.x == 0 && o.z == 0 ? &chunk : world.chunk({pos.x + o.x, pos.z + o.z});
    if (!neighbour || !faceIsOpaque(neighbour->section(s), opaque, d)) return false;
  }
  return true;
}

#if defined(__SSE2__)
// Sixteen light terms (SectionSnapshot::lightTerm) from eight bytes of each channel's nibbles and
// sixteen 0/1 opaque flags. Every term fits in 16 bits (kOpen is bit 12), so the sum is
// built in 16-bit lanes and widened at the end.
void lightRow(const std::uint8_t* block, const std::uint8_t* sky, const std::uint8_t* opaque,
              std::uint32_t* out) {
  const __m128i low = _mm_set1_epi8(kLightMask);
  auto levels = [&](const std::uint8_t* bytes) {  // 16 levels, one per byte, in cell order
    const __m128i packed = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(bytes));
    return _mm_unpacklo_epi8(_mm_and_si128(packed, low), _mm_and_si128(_mm_srli_epi16(packed, 4), low));
  };
  const __m128i b = levels(block), k = levels(sky), zero = _mm_setzero_si128();
  const __m128i open = _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(opaque)), zero);
  const __m128i kOpen = _mm_set1_epi16(static_cast<short>(SectionSnapshot::kOpen));
  auto half = [&](__m128i b16, __m128i k16, __m128i open16) {
    return _mm_and_si128(_mm_or_si128(_mm_or_si128(kOpen, b16), _mm_slli_epi16(k16, 6)), open16);
  };
  const __m128i lo =
      half(_mm_unpacklo_epi8(b, zero), _mm_unpacklo_epi8(k, zero), _mm_unpacklo_epi8(open, open));
  const __m128i hi =
      half(_mm_unpackhi_epi8(b, zero), _mm_unpackhi_epi8(k, zero), _mm_unpackhi_epi8(open, open));
  auto* dst = reinterpret_cast<__m128i*>(out);
  _mm_storeu_si128(dst, _mm_unpacklo_epi16(lo, zero));
  _mm_storeu_si128(dst + 1, _mm_unpackhi_epi16(lo, zero));
  _mm_storeu_si128(dst + 2, _mm_unpacklo_epi16(hi, zero));
  _mm_storeu_si128(dst + 3, _mm_unpackhi_epi16(hi, zero));
}
#endif

// Copies `count` cells along x, from local (x0, y, z) of `chunk`, to `out` starting at index `dst`.
// Outside the world or without a chunk: air, no light (sky kMaxLight above the world).
void copyRun(const Chunk* chunk, int y, int z, int x0, int count, const std::uint8_t* opaqueCube,
             SectionSnapshot& out, int dst) {
  const auto d = static_cast<std::size_t>(dst);
  if (!chunk || !inWorldHeight(y)) {
    std::fill_n(&out.blocks[d], count, kAir);
    std::fill_n(&out.opaque[d], count, std::uint8_t{0});
    std::fill_n(&out.light[d], count, SectionSnapshot::lightTerm(false, 0, y >= kMaxY ? kMaxLight : 0));
    return;
  }
  const int s = sectionOf(y), first = Section::index(x0, localOf(y), z);
  const Section& section = chunk->section(s);
  if (const auto* dense = section.blocks()) {
    if (count == kChunkSize) {
      std::copy_n(dense->data() + first, kChunkSize, &out.blocks[d]);  // a constant size: inlined
    } else {
      for (int i = 0; i < count; ++i)
        out.blocks[d + static_cast<std::size_t>(i)] = (*dense)[static_cast<std::size_t>(first + i)];
    }
  } else {
    std::fill_n(&out.blocks[d], count, section.uniformBlock());
  }
  std::uint8_t* opaque = &out.opaque[d];
  for (int i = 0; i < count; ++i) opaque[i] = opaqueCube[out.blocks[d + static_cast<std::size_t>(i)]];
  // An unlit chunk reads as dark bytes, so the loops below need no test per cell.
  static constexpr NibbleArray::Bytes kDark{};
  const ChunkLight& light = chunk->light();
  const std::uint8_t* block = light.lit ? light.block[static_cast<std::size_t>(s)].bytes() : kDark.data();
  const std::uint8_t* sky = light.lit ? light.sky[static_cast<std::size_t>(s)].bytes() : kDark.data();
  std::uint32_t* terms = &out.light[d];
#if defined(__SSE2__)
  if (count == kChunkSize) {  // a whole row, starting on a byte: sixteen terms in a few vector steps
    lightRow(block + first / 2, sky + first / 2, opaque, terms);
    return;
  }
#endif
  for (int i = 0; i < count; ++i) {
    terms[i] = SectionSnapshot::lightTerm(opaque[i], NibbleArray::get(block, first + i),
                                          NibbleArray::get(sky, first + i));
  }
}

}  // namespace

CaptureResult captureSection(const World& world, SectionPos pos, SectionSnapshot& out) {
  const Chunk* chunk = world.chunk({pos.x, pos.z});
  if (!chunk) return CaptureResult::Empty;
  const Section& section = chunk->section(pos.section);
  if (section.isAllAir()) return CaptureResult::Empty;
  if (section.isUniform() && world.opaqueCubes()[section.uniformBlock()] && buried(world, *chunk, pos)) {
    return CaptureResult::Buried;
  }

  out.pos = pos;
  const Chunk* columns[3][3];
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx) columns[dz + 1][dx + 1] = world.chunk({pos.x + dx, pos.z + dz});
  // columns[] of a local x or z from -1 to kChunkSize: 0 west or north, 1 this chunk, 2 east or south.
  const auto column = [](int local) { return (local + kChunkSize) / kChunkSize; };
  for (int lz = -1; lz <= kChunkSize; ++lz)
    for (int lx = -1; lx <= kChunkSize; ++lx) {
      const Chunk* owner = columns[column(lz)][column(lx)];
      out.tints[static_cast<std::size_t>((lz + 1) * SectionSnapshot::kSide + lx + 1)] =
          owner ? owner->tint(localOf(lx), localOf(lz))
                : chunk->tint(std::clamp(lx, 0, kLastCell), std::clamp(lz, 0, kLastCell));
    }
  const std::uint8_t* opaqueCube = world.opaqueCubes().data();
  const int y0 = pos.minBlockY();
  for (int ly = -1; ly <= kChunkSize; ++ly) {
    const int y = y0 + ly;
    for (int lz = -1; lz <= kChunkSize; ++lz) {
      // Each row is three runs: one cell from the west chunk, 16 from this column, one from the east.
      const int row = SectionSnapshot::index(-1, ly, lz);
      const Chunk* const* along = columns[column(lz)];
      copyRun(along[0], y, localOf(lz), kLastCell, 1, opaqueCube, out, row);
      copyRun(along[1], y, localOf(lz), 0, kChunkSize, opaqueCube, out, row + 1);
      copyRun(along[2], y, localOf(lz), 0, 1, opaqueCube, out, row + 1 + kChunkSize);
    }
  }
  return CaptureResult::Captured;
}

}  // namespace terrasol
