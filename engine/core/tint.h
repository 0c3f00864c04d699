#pragma once
// Block tints: the colour multiplied onto a grey texture. Grass, foliage and water take theirs from
// the biome the block stands in, birch and spruce leaves have Minecraft's fixed colours. Shared by
// the block registry, the biomes, the mesher (which stores a vertex's tint climate), the renderer's
// shaders and the tools that draw blocks on the CPU.

#include <algorithm>
#include <cstdint>
#include <glm/vec3.hpp>

namespace terrasol {

enum class Tint : std::uint8_t { None, Grass, Foliage, Water, Birch, Spruce };
inline constexpr int kTintCount = 6;

constexpr bool tintedByBiome(Tint tint) {
  return tint == Tint::Grass || tint == Tint::Foliage || tint == Tint::Water;
}

// Where a column's grass, foliage and water colours come from: its place on the packs' colormaps, as
// Minecraft looks a biome's temperature and downfall up there. Both axes are 0..255: `temperature`
// is the clamped temperature, `downfall` the clamped downfall times it, so the colormap's texel is
// (255 - temperature, 255 - downfall) on a 256 x 256 map. Blending biomes averages these.
struct TintClimate {
  std::uint8_t temperature, downfall;
  friend bool operator==(TintClimate, TintClimate) = default;
};

// Minecraft's lookup (ColorResolver) for a temperature and downfall, texel for texel: (1 - t) * 255
// and (1 - d) * 255 rounded down, counted here from the far side.
constexpr TintClimate tintClimate(float temperature, float downfall) {
  const float t = std::clamp(temperature, 0.0f, 1.0f);
  const float d = std::clamp(downfall, 0.0f, 1.0f) * t;
  return {static_cast<std::uint8_t>(255 - static_cast<int>((1.0f - t) * 255.0f)),
          static_cast<std::uint8_t>(255 - static_cast<int>((1.0f - d) * 255.0f))};
}
// Worlds without biomes (flat, void) are plains: temperature 0.8, downfall 0.4.
inline constexpr TintClimate kPlainsTint = tintClimate(0.8f, 0.4f);

// sRGB 0..1. Minecraft's plains grass and foliage, used where no pack has a colormap.
inline constexpr glm::vec3 kDefaultGrass{0x91 / 255.0f, 0xBD / 255.0f, 0x59 / 255.0f};
inline constexpr glm::vec3 kDefaultFoliage{0x77 / 255.0f, 0xAB / 255.0f, 0x2F / 255.0f};
// Water by temperature: its usual colour from temperature 0.5 to 0.85, bluer towards the cold (frozen
// rivers'), greener-blue towards the heat (lukewarm oceans'), so snowy lakes and desert pools differ.
inline constexpr glm::vec3 kWaterCold{0x3D / 255.0f, 0x57 / 255.0f, 0xD6 / 255.0f};
inline constexpr glm::vec3 kWaterTemperate{0x3F / 255.0f, 0x76 / 255.0f, 0xE4 / 255.0f};
inline constexpr glm::vec3 kWaterWarm{0x45 / 255.0f, 0xAD / 255.0f, 0xF2 / 255.0f};
inline constexpr float kWaterTemperateFrom = 0.5f, kWaterTemperateTo = 0.85f;
// A biome's own colour for one tinted kind, laid over the colormap's by weight / 255: Minecraft's fixed
// colours (badlands grass, cherry leaves, each biome's water) weigh 255, dark forest's darkening 128
// (it halves the colormap's colour towards its own). Averaged, weighted, where biomes blend.
struct BiomeColour {
  std::uint8_t r = 0, g = 0, b = 0, weight = 0;
  friend bool operator==(BiomeColour, BiomeColour) = default;
};

// A column's biome tint, before any pack: its place on the colormaps and its biome's own colours.
// Terrasol's generator sets only the climate; Minecraft's biomes bring their own colours too.
struct ColumnTint {
  TintClimate climate = kPlainsTint;
  BiomeColour grass{}, foliage{}, water{};
  friend bool operator==(const ColumnTint&, const ColumnTint&) = default;
};
inline constexpr ColumnTint kPlainsColumn{};
// A column with a climate and no colours of its own, as Terrasol's biomes are.
constexpr ColumnTint climateOnly(TintClimate climate) {
  ColumnTint column;
  column.climate = climate;
  return column;
}

// Minecraft's fixed birch and spruce (evergreen) leaf colours.
inline constexpr glm::vec3 kBirchFoliage{0x80 / 255.0f, 0xA7 / 255.0f, 0x55 / 255.0f};
inline constexpr glm::vec3 kSpruceFoliage{0x61 / 255.0f, 0x99 / 255.0f, 0x61 / 255.0f};

// The water colour at a tint climate's temperature (0..255). The block shaders do the same.
constexpr glm::vec3 waterTint(int temperature) {
  const float t = static_cast<float>(temperature) / 255.0f;
  auto mix = [](glm::vec3 a, glm::vec3 b, float f) { return a + (b - a) * std::clamp(f, 0.0f, 1.0f); };
  return t < kWaterTemperateFrom
             ? mix(kWaterCold, kWaterTemperate, t / kWaterTemperateFrom)
             : mix(kWaterTemperate, kWaterWarm, (t - kWaterTemperateTo) / (1.0f - kWaterTemperateTo));
}

}  // namespace terrasol
