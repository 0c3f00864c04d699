#include "minecraft/biome_table.h"

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

}  // namespace

std::optional<TintClimate> minecraftBiomeTint(std::string_view name) {
  constexpr std::string_view kMinecraft = "minecraft:";
  if (name.starts_with(kMinecraft)) name.remove_prefix(kMinecraft.size());
  for (const NamedBiome& b : kBiomes)
    if (b.name == name) return tintClimate(b.temperature, b.downfall);
  return std::nullopt;
}

std::optional<TintClimate> minecraftBiomeTint(int id) {
  for (const NumberedBiome& b : kNumberedBiomes)
    if (b.id == id) return tintClimate(b.temperature, b.downfall);
  return std::nullopt;
}

}  // namespace terrasol
