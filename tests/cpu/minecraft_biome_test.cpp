// A Minecraft save's biome tints: Minecraft's own colours per biome, swamp grass by its noise, and the
// 5 x 5 blend reaching across chunk borders.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "minecraft/biome_table.h"
#include "minecraft/minecraft_source.h"
#include "support/anvil_writer.h"
#include "support/test_data.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using namespace testing;

constexpr int kV1_20_6 = 3839;

// Chunks (0, 0) all desert and (1, 0) all swamp, stone up to y = 63; nothing west of them.
std::filesystem::path writeDesertBesideSwamp() {
  const auto dir = scratchDir("minecraft_biome_blend");
  std::filesystem::remove_all(dir);
  std::vector<RegionEntry> entries;
  for (const auto& [x, biome] : {std::pair{0, "minecraft:desert"}, std::pair{1, "minecraft:swamp"}}) {
    std::vector<TestSection> sections;
    for (int y = -4; y < 4; ++y)
      sections.push_back({.y = y, .palette = {"stone"}, .indices = {}, .biome = biome});
    entries.push_back({{x, 0}, encodeNbt(chunkNbt(kV1_20_6, {x, 0}, sections))});
  }
  writeRegion(dir / "region", entries);
  return dir;
}

TEST(MinecraftBiomes, BiomesBringMinecraftsOwnColours) {
  const auto tint = [](const char* name) { return minecraftBiomeTint(*minecraftBiome(name), 0, 0); };
  EXPECT_EQ(tint("plains").water, (BiomeColour{0x3F, 0x76, 0xE4, 255}));
  EXPECT_EQ(tint("plains").grass, BiomeColour{}) << "the colormap's";
  EXPECT_EQ(tint("warm_ocean").water, (BiomeColour{0x43, 0xD5, 0xEE, 255}));
  EXPECT_EQ(tint("badlands").grass, (BiomeColour{0x90, 0x81, 0x4D, 255}));
  EXPECT_EQ(tint("badlands").foliage, (BiomeColour{0x9E, 0x81, 0x4D, 255}));
  EXPECT_EQ(tint("cherry_grove").foliage, (BiomeColour{0xB6, 0xDB, 0x61, 255}));
  EXPECT_EQ(tint("mangrove_swamp").water, (BiomeColour{0x3A, 0x7A, 0x6A, 255}));
  EXPECT_EQ(tint("dark_forest").grass, (BiomeColour{0x28, 0x34, 0x0A, 128})) << "halfway, over the colormap";
  EXPECT_EQ(minecraftBiomeTint(*minecraftBiome(6), 0, 0).foliage, tint("swamp").foliage)
      << "1.13-1.17's numbered swamp";
  EXPECT_EQ(minecraftBiomeTint(*minecraftBiome(38), 0, 0).grass, tint("badlands").grass)
      << "and its wooded badlands plateau";
}

// Swamp grass comes in Minecraft's two colours, in patches tens of blocks across.
TEST(MinecraftBiomes, SwampGrassTakesTwoColoursInPatches) {
  const MinecraftBiome swamp = *minecraftBiome("swamp");
  const BiomeColour dark{0x4C, 0x76, 0x3C, 255}, light{0x6A, 0x70, 0x39, 255};
  int darkColumns = 0, changes = 0, pairs = 0;
  BiomeColour previous;
  for (int z = 0; z < 256; z += 4)
    for (int x = 0; x < 512; ++x) {
      const BiomeColour grass = minecraftBiomeTint(swamp, x, z).grass;
      ASSERT_TRUE(grass == dark || grass == light);
      darkColumns += grass == dark ? 1 : 0;
      if (x > 0) {
        ++pairs;
        changes += grass == previous ? 0 : 1;
      }
      previous = grass;
    }
  const int columns = 64 * 512;
  std::printf("dark %d of %d columns, %d changes of %d neighbours\n", darkColumns, columns, changes, pairs);
  EXPECT_GT(darkColumns, columns / 10);
  EXPECT_LT(darkColumns, columns * 9 / 10);
  EXPECT_LT(changes, pairs / 10) << "patches, not noise from column to column";
}

// Across the border the colours step by a fifth of the contrast per column, from the last column of
// one biome reached by the 5 x 5 blend to the first one past it; a chunk with no neighbour repeats its
// own edge.
TEST(MinecraftBiomes, TintsBlendAcrossChunkBorders) {
  const auto dir = writeDesertBesideSwamp();
  const MinecraftChunkSource source(dir, defaultBlocks());
  Chunk desert({0, 0}), swamp({1, 0});
  source.generate(desert);
  source.generate(swamp);
  const ColumnTint pureDesert = minecraftBiomeTint(*minecraftBiome("desert"), 0, 0);
  const ColumnTint pureSwamp = minecraftBiomeTint(*minecraftBiome("swamp"), 16, 0);
  // Along x, from desert's column 0 to swamp's 15: desert's columns up to 13 see no swamp.
  std::vector<ColumnTint> row;
  for (int x = 0; x < 16; ++x) row.push_back(desert.tint(x, 8));
  for (int x = 0; x < 16; ++x) row.push_back(swamp.tint(x, 8));
  for (int x = 0; x <= 13; ++x) EXPECT_EQ(row[static_cast<std::size_t>(x)], pureDesert) << "x = " << x;
  for (int x = 18; x < 32; ++x)
    EXPECT_EQ(row[static_cast<std::size_t>(x)].water, pureSwamp.water) << "x = " << x;
  for (int x = 14; x <= 17; ++x) {
    const int swampColumns = x - 13;  // of the five around x
    const auto mean = [&](int d, int s) {
      return static_cast<int>(std::lround((d * (5 - swampColumns) + s * swampColumns) / 5.0));
    };
    const ColumnTint& t = row[static_cast<std::size_t>(x)];
    EXPECT_EQ(t.climate.temperature, mean(pureDesert.climate.temperature, pureSwamp.climate.temperature));
    EXPECT_EQ(t.water.r, mean(pureDesert.water.r, pureSwamp.water.r)) << "x = " << x;
    EXPECT_EQ(t.water.weight, 255);
    EXPECT_EQ(t.foliage, (BiomeColour{0x6A, 0x70, 0x39, static_cast<std::uint8_t>(mean(0, 255))}))
        << "swamp leaves' colour, as strong as the swamp's share; x = " << x;
  }
  Chunk again({0, 0});
  source.fillTints(again);
  for (int x = 0; x < 16; ++x)
    EXPECT_EQ(again.tint(x, 8), desert.tint(x, 8)) << "tints again, for an overlay's chunk";
  EXPECT_EQ(source.unknownCells(), 0u);
  EXPECT_TRUE(source.problems().empty());
}

}  // namespace
}  // namespace terrasol
