#include "world/biomes.h"

#include <algorithm>

#include "core/enum_names.h"
#include "world/terrain_generator.h"

namespace terrasol {

std::string_view biomeName(Biome biome) {
  static constexpr EnumNames<Biome, kBiomeCount> kNames{{"ocean", "beach", "plains", "forest", "birch_forest",
                                                         "taiga", "snowy_plains", "desert", "savanna",
                                                         "stony_peaks"}};
  return kNames.nameOf(biome);
}

TintClimate biomeTint(Biome biome) {
  struct Weather {
    float temperature, downfall;
  };
  static constexpr Weather kWeather[kBiomeCount] = {
      {0.5f, 0.5f},   // ocean
      {0.8f, 0.4f},   // beach
      {0.8f, 0.4f},   // plains
      {0.7f, 0.8f},   // forest
      {0.6f, 0.6f},   // birch forest
      {0.25f, 0.8f},  // taiga
      {0.0f, 0.5f},   // snowy plains
      {2.0f, 0.0f},   // desert
      {2.0f, 0.0f},   // savanna
      {1.0f, 0.3f},   // stony peaks
  };
  const Weather w = kWeather[static_cast<int>(biome)];
  return tintClimate(w.temperature, w.downfall);
}

BiomeSource::BiomeSource(std::uint64_t seed) : temperature_(seed ^ 0x0B10), humidity_(seed ^ 0x0B11) {}

Climate BiomeSource::climate(int x, int z, int height) const {
  const double t = temperature_.fractal(x / 1100.0, z / 1100.0, 3) * 2.4 - std::max(0, height - 90) / 80.0;
  const double h = humidity_.fractal(x / 900.0, z / 900.0, 3) * 2.4;
  return {std::clamp(t, -1.0, 1.0), std::clamp(h, -1.0, 1.0)};
}

Biome BiomeSource::biomeAt(int x, int z, int height) const {
  if (height < TerrainGenerator::kSeaLevel - 3) return Biome::Ocean;
  if (height >= 118) return Biome::StonyPeaks;
  const Climate c = climate(x, z, height);
  if (height <= TerrainGenerator::kSeaLevel + 1)
    return c.temperature < -0.4 ? Biome::SnowyPlains : Biome::Beach;
  if (c.temperature < -0.4) return Biome::SnowyPlains;
  if (c.temperature < -0.05) return c.humidity > 0.0 ? Biome::Taiga : Biome::Plains;
  if (c.temperature < 0.45)
    return c.humidity > 0.2 ? Biome::Forest : c.humidity > -0.15 ? Biome::BirchForest : Biome::Plains;
  return c.humidity < 0.05 ? Biome::Desert : Biome::Savanna;
}

}  // namespace terrasol
