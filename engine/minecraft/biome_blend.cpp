#include "minecraft/biome_blend.h"

#include <algorithm>

#include "core/assert.h"

namespace terrasol {
namespace {

// Sums of a BiomeColour over columns: rgb weighted by each column's weight.
struct ColourSum {
  int r = 0, g = 0, b = 0, weight = 0;
  void add(BiomeColour c) {
    r += c.r * c.weight;
    g += c.g * c.weight;
    b += c.b * c.weight;
    weight += c.weight;
  }
  BiomeColour mean(int columns) const {
    if (weight == 0) return {};
    const auto of = [&](int sum) { return static_cast<std::uint8_t>((sum + weight / 2) / weight); };
    return {of(r), of(g), of(b), static_cast<std::uint8_t>((weight + columns / 2) / columns)};
  }
};

}  // namespace

ColumnTints columnTintsOf(const Chunk& chunk) {
  ColumnTints tints;
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x)
      tints[static_cast<std::size_t>(columnIndex(x, z))] = chunk.tint(x, z);
  return tints;
}

void blendBiomeTints(const std::array<const ColumnTints*, 9>& around, Chunk& chunk) {
  const ColumnTints* centre = around[4];
  TERRASOL_ASSERT(centre != nullptr, "biome blend: no tints for the chunk itself");
  const auto at = [&](int x, int z) -> const ColumnTint& {
    const int dx = x < 0 ? -1 : x >= kChunkSize ? 1 : 0, dz = z < 0 ? -1 : z >= kChunkSize ? 1 : 0;
    if (const ColumnTints* t = around[static_cast<std::size_t>((dz + 1) * 3 + dx + 1)])
      return (*t)[static_cast<std::size_t>(columnIndex(x - dx * kChunkSize, z - dz * kChunkSize))];
    return (*centre)[static_cast<std::size_t>(
        columnIndex(std::clamp(x, 0, kChunkSize - 1), std::clamp(z, 0, kChunkSize - 1)))];
  };
  constexpr int kColumns = (2 * kBiomeBlendRadius + 1) * (2 * kBiomeBlendRadius + 1);
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      int temperature = 0, downfall = 0;
      ColourSum grass, foliage, water;
      for (int dz = -kBiomeBlendRadius; dz <= kBiomeBlendRadius; ++dz)
        for (int dx = -kBiomeBlendRadius; dx <= kBiomeBlendRadius; ++dx) {
          const ColumnTint& t = at(x + dx, z + dz);
          temperature += t.climate.temperature;
          downfall += t.climate.downfall;
          grass.add(t.grass);
          foliage.add(t.foliage);
          water.add(t.water);
        }
      const auto mean = [](int sum) { return static_cast<std::uint8_t>((sum + kColumns / 2) / kColumns); };
      chunk.setTint(x, z,
                    {{mean(temperature), mean(downfall)},
                     grass.mean(kColumns),
                     foliage.mean(kColumns),
                     water.mean(kColumns)});
    }
}

}  // namespace terrasol
