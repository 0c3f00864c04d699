#include "mesh/vertex_tints.h"

#include <array>

namespace terrasol {

// Most vertices sit on a block corner, where the climate is the four columns' mean: those come
// from a table.
void applyTints(PackedVertices& vertices, const SectionSnapshot& s) {
  // Both axes at once, in two 32-bit lanes of one word.
  auto lanes = [&](int x, int z) {
    const TintClimate t = s.tint(x, z);
    return std::uint64_t{t.temperature} | std::uint64_t{t.downfall} << 32;
  };
  // The four columns around (x, z) in 1/32 block from the centre of column -1, weighted and summed:
  // 1024 times the climate there.
  auto bilinear = [&](int u, int w) {
    const int i = u / 32 - 1, j = w / 32 - 1, fx = u % 32, fz = w % 32;
    const std::uint64_t sum = lanes(i, j) * static_cast<std::uint64_t>((32 - fx) * (32 - fz)) +
                              lanes(i + 1, j) * static_cast<std::uint64_t>(fx * (32 - fz)) +
                              lanes(i, j + 1) * static_cast<std::uint64_t>((32 - fx) * fz) +
                              lanes(i + 1, j + 1) * static_cast<std::uint64_t>(fx * fz) +
                              (512ull | 512ull << 32);
    return PackedVertex::packTintClimate(static_cast<int>((sum & 0xFFFFFFFF) >> 10),
                                         static_cast<int>(sum >> 42));
  };
  constexpr int kCorners = kChunkSize + 1;  // block corners along a section's side
  std::array<std::uint32_t, kCorners * kCorners> corners;
  for (int z = 0; z < kCorners; ++z)
    for (int x = 0; x < kCorners; ++x)
      corners[static_cast<std::size_t>(z * kCorners + x)] = bilinear(x * 32 + 16, z * 32 + 16);
  for (PackedVertex& v : vertices) {
    if (!tintedByBiome(static_cast<Tint>(v.tint()))) continue;
    const int x32 = v.x32(), z32 = v.z32();
    const std::uint32_t bits = (x32 | z32) % 32 == 0
                                   ? corners[static_cast<std::size_t>(z32 / 32 * kCorners + x32 / 32)]
                                   : bilinear(x32 + 16, z32 + 16);
    v.light = (v.light & ~PackedVertex::kTintClimateBits) | bits;
  }
}

void applyUniformTint(PackedVertices& vertices, TintClimate climate) {
  const std::uint32_t bits = PackedVertex::packTintClimate(climate.temperature, climate.downfall);
  for (PackedVertex& v : vertices) {
    if (tintedByBiome(static_cast<Tint>(v.tint()))) v.light |= bits;
  }
}

}  // namespace terrasol
