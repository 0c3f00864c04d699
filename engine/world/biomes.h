#pragma once
// Where the terrain generator's biomes lie: each column's biome from its height (oceans, beaches,
// stony peaks) and, on land, from a smooth climate (temperature and humidity noise on a scale of
// about a thousand blocks, cooler higher up), so biomes are deterministic per seed and their borders
// follow the noise's smooth contours. Plain C++.

#include <cstdint>
#include <string_view>

#include "core/tint.h"
#include "world/noise.h"

namespace terrasol {

enum class Biome : std::uint8_t {
  Ocean,
  Beach,
  Plains,
  Forest,
  BirchForest,
  Taiga,
  SnowyPlains,
  Desert,
  Savanna,
  StonyPeaks
};
inline constexpr int kBiomeCount = 10;

// Minecraft's name for it ("birch_forest").
std::string_view biomeName(Biome biome);

struct Climate {
  double temperature, humidity;  // about -1..1
};

// Minecraft's temperature and downfall of each biome (plains 0.8 and 0.4, desert 2 and 0, ...).
TintClimate biomeTint(Biome biome);

class BiomeSource {
 public:
  explicit BiomeSource(std::uint64_t seed);

  // The climate of a column whose surface is at `height`: the air cools above y = 90.
  Climate climate(int x, int z, int height) const;
  // The biome of a column whose surface is at `height` (TerrainGenerator::surfaceHeight).
  Biome biomeAt(int x, int z, int height) const;

 private:
  Noise temperature_, humidity_;
};

}  // namespace terrasol
