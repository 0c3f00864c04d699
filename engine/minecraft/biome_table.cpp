#include "minecraft/biome_table.h"

#include <array>
#include <utility>
#include <vector>

#include "minecraft/swamp_noise.h"

namespace terrasol {
namespace {

struct NamedBiome {
  std::string_view name;
  float temperature, downfall;
};
constexpr NamedBiome kBiomes[] = {
    {"badlands", 2.0f, 0.0f},
    {"bamboo_jungle", 0.95f, 0.9f},
    {"basalt_deltas", 2.0f, 0.0f},
    {"beach", 0.8f, 0.4f},
    {"birch_forest", 0.6f, 0.6f},
    {"cherry_grove", 0.5f, 0.8f},
    {"cold_ocean", 0.5f, 0.5f},
    {"crimson_forest", 2.0f, 0.0f},
    {"dark_forest", 0.7f, 0.8f},
    {"deep_cold_ocean", 0.5f, 0.5f},
    {"deep_dark", 0.8f, 0.4f},
    {"deep_frozen_ocean", 0.5f, 0.5f},
    {"deep_lukewarm_ocean", 0.5f, 0.5f},
    {"deep_ocean", 0.5f, 0.5f},
    {"desert", 2.0f, 0.0f},
    {"dripstone_caves", 0.8f, 0.4f},
    {"end_barrens", 0.5f, 0.5f},
    {"end_highlands", 0.5f, 0.5f},
    {"end_midlands", 0.5f, 0.5f},
    {"eroded_badlands", 2.0f, 0.0f},
    {"flower_forest", 0.7f, 0.8f},
    {"forest", 0.7f, 0.8f},
    {"frozen_ocean", 0.0f, 0.5f},
    {"frozen_peaks", -0.7f, 0.9f},
    {"frozen_river", 0.0f, 0.5f},
    {"grove", -0.2f, 0.8f},
    {"ice_spikes", 0.0f, 0.5f},
    {"jagged_peaks", -0.7f, 0.9f},
    {"jungle", 0.95f, 0.9f},
    {"lukewarm_ocean", 0.5f, 0.5f},
    {"lush_caves", 0.5f, 0.5f},
    {"mangrove_swamp", 0.8f, 0.9f},
    {"meadow", 0.5f, 0.8f},
    {"mushroom_fields", 0.9f, 1.0f},
    {"nether_wastes", 2.0f, 0.0f},
    {"ocean", 0.5f, 0.5f},
    {"old_growth_birch_forest", 0.6f, 0.6f},
    {"old_growth_pine_taiga", 0.3f, 0.8f},
    {"old_growth_spruce_taiga", 0.25f, 0.8f},
    {"pale_garden", 0.7f, 0.8f},
    {"plains", 0.8f, 0.4f},
    {"river", 0.5f, 0.5f},
    {"savanna", 2.0f, 0.0f},
    {"savanna_plateau", 2.0f, 0.0f},
    {"small_end_islands", 0.5f, 0.5f},
    {"snowy_beach", 0.05f, 0.3f},
    {"snowy_plains", 0.0f, 0.5f},
    {"snowy_slopes", -0.3f, 0.9f},
    {"snowy_taiga", -0.5f, 0.4f},
    {"soul_sand_valley", 2.0f, 0.0f},
    {"sparse_jungle", 0.95f, 0.8f},
    {"stony_peaks", 1.0f, 0.3f},
    {"stony_shore", 0.2f, 0.3f},
    {"sunflower_plains", 0.8f, 0.4f},
    {"swamp", 0.8f, 0.9f},
    {"taiga", 0.25f, 0.8f},
    {"the_end", 0.5f, 0.5f},
    {"the_void", 0.5f, 0.5f},
    {"warm_ocean", 0.5f, 0.5f},
    {"warped_forest", 2.0f, 0.0f},
    {"windswept_forest", 0.2f, 0.3f},
    {"windswept_gravelly_hills", 0.2f, 0.3f},
    {"windswept_hills", 0.2f, 0.3f},
    {"windswept_savanna", 2.0f, 0.0f},
    {"wooded_badlands", 2.0f, 0.0f},
};

struct NumberedBiome {
  int id;
  float temperature, downfall;
};
constexpr NumberedBiome kNumberedBiomes[] = {
    {0, 0.5f, 0.5f},    {1, 0.8f, 0.4f},    {2, 2.0f, 0.0f},   {3, 0.2f, 0.3f},    {4, 0.7f, 0.8f},
    {5, 0.25f, 0.8f},   {6, 0.8f, 0.9f},    {7, 0.5f, 0.5f},   {8, 2.0f, 0.0f},    {9, 0.5f, 0.5f},
    {10, 0.0f, 0.5f},   {11, 0.0f, 0.5f},   {12, 0.0f, 0.5f},  {13, 0.0f, 0.5f},   {14, 0.9f, 1.0f},
    {15, 0.9f, 1.0f},   {16, 0.8f, 0.4f},   {17, 2.0f, 0.0f},  {18, 0.7f, 0.8f},   {19, 0.25f, 0.8f},
    {20, 0.2f, 0.3f},   {21, 0.95f, 0.9f},  {22, 0.95f, 0.9f}, {23, 0.95f, 0.8f},  {24, 0.5f, 0.5f},
    {25, 0.2f, 0.3f},   {26, 0.05f, 0.3f},  {27, 0.6f, 0.6f},  {28, 0.6f, 0.6f},   {29, 0.7f, 0.8f},
    {30, -0.5f, 0.4f},  {31, -0.5f, 0.4f},  {32, 0.3f, 0.8f},  {33, 0.3f, 0.8f},   {34, 0.2f, 0.3f},
    {35, 1.2f, 0.0f},   {36, 1.0f, 0.0f},   {37, 2.0f, 0.0f},  {38, 2.0f, 0.0f},   {39, 2.0f, 0.0f},
    {40, 0.5f, 0.5f},   {41, 0.5f, 0.5f},   {42, 0.5f, 0.5f},  {43, 0.5f, 0.5f},   {44, 0.5f, 0.5f},
    {45, 0.5f, 0.5f},   {46, 0.5f, 0.5f},   {47, 0.5f, 0.5f},  {48, 0.5f, 0.5f},   {49, 0.5f, 0.5f},
    {50, 0.5f, 0.5f},   {127, 0.5f, 0.5f},  {129, 0.8f, 0.4f}, {130, 2.0f, 0.0f},  {131, 0.2f, 0.3f},
    {132, 0.7f, 0.8f},  {133, 0.25f, 0.8f}, {134, 0.8f, 0.9f}, {140, 0.0f, 0.5f},  {149, 0.95f, 0.9f},
    {151, 0.95f, 0.8f}, {155, 0.6f, 0.6f},  {156, 0.6f, 0.6f}, {157, 0.7f, 0.8f},  {158, -0.5f, 0.4f},
    {160, 0.25f, 0.8f}, {161, 0.25f, 0.8f}, {162, 0.2f, 0.3f}, {163, 1.1f, 0.0f},  {164, 1.0f, 0.0f},
    {165, 2.0f, 0.0f},  {166, 2.0f, 0.0f},  {167, 2.0f, 0.0f}, {168, 0.95f, 0.9f}, {169, 0.95f, 0.9f},
    {170, 2.0f, 0.0f},  {171, 2.0f, 0.0f},  {172, 2.0f, 0.0f}, {173, 2.0f, 0.0f},
};

// Biomes whose effects name colours of their own (Minecraft's worldgen biome definitions, effects:
// grass_color, foliage_color, water_color, grass_color_modifier). Every other biome: the colormaps'
// grass and foliage, and water 0x3F76E4.
enum class GrassModifier : std::uint8_t { None, DarkForest, Swamp };
struct OwnColours {
  std::string_view name;
  std::uint32_t grass = 0, foliage = 0, water = 0;  // 0: none of its own
  GrassModifier modifier = GrassModifier::None;
};
constexpr std::uint32_t kWater = 0x3F76E4, kColdWater = 0x3D57D6, kFrozenWater = 0x3938C9;
constexpr OwnColours kOwnColours[] = {
    {"badlands", 0x90814D, 0x9E814D},
    {"eroded_badlands", 0x90814D, 0x9E814D},
    {"wooded_badlands", 0x90814D, 0x9E814D},
    {"cherry_grove", 0xB6DB61, 0xB6DB61, 0x5DB7EF},
    {"pale_garden", 0x778272, 0x878D76, 0x76889D},
    {"dark_forest", 0, 0, 0, GrassModifier::DarkForest},
    {"swamp", 0, 0x6A7039, 0x617B64, GrassModifier::Swamp},
    {"mangrove_swamp", 0, 0x8DB127, 0x3A7A6A, GrassModifier::Swamp},
    {"meadow", 0, 0, 0x0E4ECF},
    {"warm_ocean", 0, 0, 0x43D5EE},
    {"lukewarm_ocean", 0, 0, 0x45ADF2},
    {"deep_lukewarm_ocean", 0, 0, 0x45ADF2},
    {"cold_ocean", 0, 0, kColdWater},
    {"deep_cold_ocean", 0, 0, kColdWater},
    {"snowy_taiga", 0, 0, kColdWater},
    {"snowy_beach", 0, 0, kColdWater},
    {"frozen_ocean", 0, 0, kFrozenWater},
    {"deep_frozen_ocean", 0, 0, kFrozenWater},
    {"frozen_river", 0, 0, kFrozenWater},
};
// 1.13 to 1.17's numeric ids of the same biomes and their variants of then (hills, plateaus,
// mountains), by today's name.
constexpr std::pair<int, std::string_view> kNumberedOwnColours[] = {
    {6, "swamp"},           {134, "swamp"},      {29, "dark_forest"},  {157, "dark_forest"},
    {37, "badlands"},       {38, "badlands"},    {39, "badlands"},     {165, "badlands"},
    {166, "badlands"},      {167, "badlands"},   {10, "frozen_ocean"}, {11, "frozen_river"},
    {50, "frozen_ocean"},   {44, "warm_ocean"},  {47, "warm_ocean"},   {45, "lukewarm_ocean"},
    {48, "lukewarm_ocean"}, {46, "cold_ocean"},  {49, "cold_ocean"},   {26, "snowy_beach"},
    {30, "snowy_taiga"},    {31, "snowy_taiga"}, {158, "snowy_taiga"},
};

constexpr std::size_t kNamedCount = std::size(kBiomes);

const OwnColours* ownColoursOf(std::string_view name) {
  for (const OwnColours& c : kOwnColours)
    if (c.name == name) return &c;
  return nullptr;
}

const OwnColours* ownColoursOf(MinecraftBiome biome) {
  if (biome < kNamedCount) return ownColoursOf(kBiomes[biome].name);
  const int id = kNumberedBiomes[biome - kNamedCount].id;
  for (const auto& [numbered, name] : kNumberedOwnColours)
    if (numbered == id) return ownColoursOf(name);
  return nullptr;
}

BiomeColour fixed(std::uint32_t rgb, std::uint8_t weight = 255) {
  return {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8),
          static_cast<std::uint8_t>(rgb), weight};
}

// Every biome's tint but swamp grass's, and whether it is a swamp's: made once, looked up per column.
struct BiomeTint {
  ColumnTint tint;
  bool swamp = false;
};

BiomeTint biomeTintOf(MinecraftBiome biome) {
  BiomeTint b;
  b.tint.climate = biome < kNamedCount ? tintClimate(kBiomes[biome].temperature, kBiomes[biome].downfall)
                                       : tintClimate(kNumberedBiomes[biome - kNamedCount].temperature,
                                                     kNumberedBiomes[biome - kNamedCount].downfall);
  b.tint.water = fixed(kWater);
  const OwnColours* own = ownColoursOf(biome);
  if (!own) return b;
  if (own->grass) b.tint.grass = fixed(own->grass);
  if (own->foliage) b.tint.foliage = fixed(own->foliage);
  if (own->water) b.tint.water = fixed(own->water);
  // Dark forest: (colour & 0xFEFEFE) + 0x28340A >> 1, halfway to 0x28340A.
  if (own->modifier == GrassModifier::DarkForest) b.tint.grass = fixed(0x28340A, 128);
  b.swamp = own->modifier == GrassModifier::Swamp;
  return b;
}

const std::vector<BiomeTint>& biomeTints() {
  static const std::vector<BiomeTint> tints = [] {
    std::vector<BiomeTint> all;
    for (std::size_t b = 0; b < kNamedCount + std::size(kNumberedBiomes); ++b)
      all.push_back(biomeTintOf(static_cast<MinecraftBiome>(b)));
    return all;
  }();
  return tints;
}

}  // namespace

std::optional<MinecraftBiome> minecraftBiome(std::string_view name) {
  constexpr std::string_view kMinecraft = "minecraft:";
  if (name.starts_with(kMinecraft)) name.remove_prefix(kMinecraft.size());
  for (std::size_t i = 0; i < kNamedCount; ++i)
    if (kBiomes[i].name == name) return static_cast<MinecraftBiome>(i);
  return std::nullopt;
}

std::optional<MinecraftBiome> minecraftBiome(int id) {
  for (std::size_t i = 0; i < std::size(kNumberedBiomes); ++i)
    if (kNumberedBiomes[i].id == id) return static_cast<MinecraftBiome>(kNamedCount + i);
  return std::nullopt;
}

MinecraftBiome minecraftPlains() {
  static const MinecraftBiome plains = *minecraftBiome("plains");
  return plains;
}

ColumnTint minecraftBiomeTint(MinecraftBiome biome, int x, int z) {
  const BiomeTint& b = biomeTints()[biome];
  if (!b.swamp) return b.tint;
  ColumnTint tint = b.tint;
  tint.grass = fixed(swampGrassNoise(x, z) < -0.1 ? 0x4C763C : 0x6A7039);
  return tint;
}

}  // namespace terrasol
