#include "mesh/vertex_tints.h"

#include <array>
#include <optional>

namespace terrasol {
namespace {

// The three channels of a colour in 21-bit lanes of one word, so one multiply weighs all three: a
// channel times the bilinear weights' sum (1024) stays below 2^21.
constexpr int kLane = 21;
constexpr std::uint64_t kLaneMask = (1ull << kLane) - 1;

std::uint64_t lanes(glm::u8vec3 c) {
  return std::uint64_t{c.r} | std::uint64_t{c.g} << kLane | std::uint64_t{c.b} << 2 * kLane;
}

// One biome tint's colours over a section: per column, and at every block corner.
class TintField {
 public:
  TintField(const SectionSnapshot& s, const TintPalette& palette, Tint tint) {
    // Neighbouring columns mostly share their tint: each run is looked up once.
    for (std::size_t i = 0; i < columns_.size(); ++i)
      columns_[i] =
          i > 0 && s.tints[i] == s.tints[i - 1] ? columns_[i - 1] : lanes(palette.rgb(tint, s.tints[i]));
    // Most vertices sit on a block corner, where the colour is the four columns' mean.
    for (int z = 0; z < kCorners; ++z)
      for (int x = 0; x < kCorners; ++x)
        corners_[static_cast<std::size_t>(z * kCorners + x)] = bilinear(x * 32 + 16, z * 32 + 16);
  }

  PackedVertex::TintBits at(int x32, int z32) const {
    return (x32 | z32) % 32 == 0 ? corners_[static_cast<std::size_t>(z32 / 32 * kCorners + x32 / 32)]
                                 : bilinear(x32 + 16, z32 + 16);
  }

 private:
  static constexpr int kCorners = kChunkSize + 1;  // block corners along a section's side

  std::uint64_t column(int x, int z) const {
    return columns_[static_cast<std::size_t>((z + 1) * SectionSnapshot::kSide + x + 1)];
  }
  // The four columns around (u, w), in 1/32 block from the centre of column -1, weighted and summed.
  PackedVertex::TintBits bilinear(int u, int w) const {
    const int i = u / 32 - 1, j = w / 32 - 1, fx = u % 32, fz = w % 32;
    constexpr std::uint64_t kHalf = 512ull | 512ull << kLane | 512ull << 2 * kLane;
    const std::uint64_t sum = column(i, j) * static_cast<std::uint64_t>((32 - fx) * (32 - fz)) +
                              column(i + 1, j) * static_cast<std::uint64_t>(fx * (32 - fz)) +
                              column(i, j + 1) * static_cast<std::uint64_t>((32 - fx) * fz) +
                              column(i + 1, j + 1) * static_cast<std::uint64_t>(fx * fz) + kHalf;
    const auto channel = [&](int lane) {
      return static_cast<std::uint8_t>((sum >> (lane * kLane) & kLaneMask) >> 10);
    };
    return PackedVertex::packTint({channel(0), channel(1), channel(2)});
  }

  std::array<std::uint64_t, SectionSnapshot::kSide * SectionSnapshot::kSide> columns_;
  std::array<PackedVertex::TintBits, kCorners * kCorners> corners_;
};

}  // namespace

void applyTints(PackedVertices& vertices, const SectionSnapshot& s, const TintPalette& palette) {
  // Made on the first vertex of each tint: most sections hold one or two.
  std::array<std::optional<TintField>, kTintCount> fields;
  std::array<PackedVertex::TintBits, kTintCount> fixed;
  for (int t = 0; t < kTintCount; ++t)
    if (!tintedByBiome(static_cast<Tint>(t)))
      fixed[static_cast<std::size_t>(t)] = PackedVertex::packTint(palette.rgb(static_cast<Tint>(t)));
  for (PackedVertex& v : vertices) {
    const auto tint = static_cast<Tint>(v.tint());
    if (tint == Tint::None) continue;
    if (!tintedByBiome(tint)) {
      v.setTint(fixed[static_cast<std::size_t>(tint)]);
      continue;
    }
    std::optional<TintField>& field = fields[static_cast<std::size_t>(tint)];
    if (!field) field.emplace(s, palette, tint);
    v.setTint(field->at(v.x32(), v.z32()));
  }
}

void applyUniformTint(PackedVertices& vertices, const ColumnTint& column, const TintPalette& palette) {
  std::array<PackedVertex::TintBits, kTintCount> bits;
  for (int t = 0; t < kTintCount; ++t)
    bits[static_cast<std::size_t>(t)] = PackedVertex::packTint(palette.rgb(static_cast<Tint>(t), column));
  for (PackedVertex& v : vertices) {
    if (v.tint() != static_cast<int>(Tint::None)) v.setTint(bits[static_cast<std::size_t>(v.tint())]);
  }
}

}  // namespace terrasol
