// Biome tints: the colormaps' lookup, the default pack's maps, biomes' own colours, the blend across
// biome borders, the colour each vertex carries, and a loaded chunk getting its tints back.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <glm/common.hpp>
#include <thread>

#include "assets/tints.h"
#include "core/paths.h"
#include "packgen.h"
#include "support/mesh_world.h"
#include "support/pack_builder.h"
#include "support/test_data.h"
#include "support/world_support.h"
#include "world/chunk_loader.h"
#include "world/terrain_generator.h"
#include "world/world_storage.h"

namespace terrasol {
namespace {

TintPalette defaultPalette() {
  std::vector<PackProblem> problems;
  TintPalette palette = loadColormaps(testing::stackOf({resourcePackDir() / "default"}), problems);
  EXPECT_TRUE(problems.empty());
  return palette;
}

// 256 x 256, texel (x, y) = (x, y, 7): a climate's colour names its texel.
Colormap gradientMap() {
  Colormap map{256, 256, {}};
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x)
      map.rgb.insert(map.rgb.end(), {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 7});
  return map;
}

glm::vec3 rgb(std::uint32_t c) {
  return glm::vec3(c >> 16 & 255, c >> 8 & 255, c & 255) / 255.0f;
}

// A border between forest and desert for seed 1 lies in the 8 x 8 chunks from here.
constexpr int kBorderChunkX = -28, kBorderChunkZ = 28;
// Minecraft's default blend (5 x 5 columns) steps by a fifth of the contrast; ours is gentler.
constexpr float kBlendStepLimit = 6.0f / 255.0f;

float largestChannelStep(glm::vec3 a, glm::vec3 b) {
  const glm::vec3 d = glm::abs(a - b);
  return std::max({d.r, d.g, d.b});
}

TEST(Tints, ColormapsAreSampledLikeMinecraftAndDefaultsFillIn) {
  const TintPalette maps(gradientMap(), gradientMap());
  // Minecraft's texel for plains: x = (int)((1 - 0.8f) * 255) = 50 (0.8f is a little above 0.8),
  // y = (int)(0.68 * 255) = 173. The tint climate names it, and the palette reads it.
  EXPECT_EQ(kPlainsTint, (TintClimate{255 - 50, 255 - 173}));
  EXPECT_EQ(maps.rgb(Tint::Grass), glm::u8vec3(50, 173, 7));
  EXPECT_EQ(maps.rgb(Tint::Foliage, climateOnly(tintClimate(5.0f, -3.0f))), glm::u8vec3(0, 255, 7))
      << "clamped, never outside the map";
  EXPECT_EQ(maps.colour(Tint::None), glm::vec3(1.0f));

  testing::PackBuilder pack("pack_tints");
  std::vector<PackProblem> problems;
  const TintPalette none = loadColormaps(testing::stackOf({pack.dir()}), problems);
  EXPECT_LT(largestChannelStep(none.colour(Tint::Grass), kDefaultGrass), 0.5f / 255.0f);
  EXPECT_LT(
      largestChannelStep(none.colour(Tint::Foliage, climateOnly(tintClimate(2.0f, 0.0f))), kDefaultFoliage),
      0.5f / 255.0f)
      << "without a colormap every climate gets Minecraft's default";
  pack.asset("textures/colormap/grass.png", "not a png");
  loadColormaps(testing::stackOf({pack.dir()}), problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("grass.png"), std::string::npos) << problems[0].message;
  problems.clear();
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const TintPalette real =
      loadColormaps(testing::stackOf({testing::testData() / "packs" / "pixel_perfection_ce"}), problems);
  EXPECT_TRUE(problems.empty());
  const glm::vec3 grass = real.colour(Tint::Grass);
  EXPECT_GT(largestChannelStep(grass, kDefaultGrass), 1.0f / 255.0f)
      << "pixel_perfection_ce's grass colormap is used";
  EXPECT_GT(grass.g, grass.b) << "and it is green";
}

// The default pack ships colormaps whose plains texels are Minecraft's plains colours; other climates
// move the way Minecraft's maps do. The committed maps are what the pack generator makes.
TEST(Tints, DefaultPackColormapsGiveMinecraftsColours) {
  const TintPalette maps = defaultPalette();
  ASSERT_EQ(maps.grass().width, 256);
  EXPECT_LT(largestChannelStep(maps.colour(Tint::Grass), kDefaultGrass), 1.5f / 255.0f);
  EXPECT_LT(largestChannelStep(maps.colour(Tint::Foliage), kDefaultFoliage), 1.5f / 255.0f);
  const auto in = [](Biome b) { return climateOnly(biomeTint(b)); };
  const glm::vec3 desert = maps.colour(Tint::Grass, in(Biome::Desert));
  const glm::vec3 forest = maps.colour(Tint::Grass, in(Biome::Forest));
  const glm::vec3 snowy = maps.colour(Tint::Grass, in(Biome::SnowyPlains));
  EXPECT_GT(desert.r, forest.r + 0.2f) << "dry heat yellows the grass";
  EXPECT_GT(snowy.b, forest.b + 0.15f) << "cold blues it";
  EXPECT_EQ(maps.colour(Tint::Birch, in(Biome::Desert)), kBirchFoliage) << "fixed, whatever the biome";
  EXPECT_EQ(maps.colour(Tint::Spruce, in(Biome::Taiga)), kSpruceFoliage);

  for (const auto& c : packgen::generateColormaps()) {
    const Image committed = loadImage(resourcePackDir() / "default" / "assets" / "minecraft" / "textures" /
                                      "colormap" / (c.name + ".png"));
    EXPECT_EQ(committed.rgba, c.map.rgba) << c.name;
  }
}

TEST(Tints, WaterIsBluerInTheColdAndTurquoiseInTheHeat) {
  const TintPalette maps = defaultPalette();
  const auto water = [&](Biome b) { return maps.colour(Tint::Water, climateOnly(biomeTint(b))); };
  EXPECT_EQ(water(Biome::Plains), kWaterTemperate);
  EXPECT_EQ(water(Biome::Ocean), kWaterTemperate);
  EXPECT_EQ(water(Biome::SnowyPlains), kWaterCold);
  EXPECT_EQ(water(Biome::Desert), kWaterWarm);
  const glm::vec3 taiga = water(Biome::Taiga);
  EXPECT_GT(taiga.g, kWaterCold.g);
  EXPECT_LT(taiga.g, kWaterTemperate.g);
}

// A biome's own colour lies over the colormap's by its weight: whole for Minecraft's fixed colours,
// half for dark forest's darkening, which Minecraft computes as ((c & 0xFEFEFE) + 0x28340A) >> 1.
TEST(Tints, ABiomesOwnColourLiesOverTheColormapsByItsWeight) {
  const TintPalette maps(gradientMap(), gradientMap());
  ColumnTint badlands = climateOnly(tintClimate(2.0f, 0.0f));
  badlands.grass = {0x90, 0x81, 0x4D, 255};
  EXPECT_EQ(maps.colour(Tint::Grass, badlands), rgb(0x90814D));
  EXPECT_EQ(maps.rgb(Tint::Foliage, badlands), glm::u8vec3(0, 255, 7)) << "the colormap, where it has none";
  ColumnTint darkForest = climateOnly(tintClimate(0.7f, 0.8f));
  const glm::u8vec3 map = maps.rgb(Tint::Grass, darkForest);
  darkForest.grass = {0x28, 0x34, 0x0A, 128};
  const glm::u8vec3 dark = maps.rgb(Tint::Grass, darkForest);
  for (int c = 0; c < 3; ++c) {
    const int minecraft = ((map[c] & 0xFE) + std::array{0x28, 0x34, 0x0A}[static_cast<std::size_t>(c)]) >> 1;
    EXPECT_NEAR(dark[c], minecraft, 1) << "channel " << c;
  }
  ColumnTint swampWater;
  swampWater.water = {0x61, 0x7B, 0x64, 255};
  EXPECT_EQ(maps.colour(Tint::Water, swampWater), rgb(0x617B64));
}

// Across a border between forest and desert, neighbouring columns' grass differs by at most a few
// levels, while the two sides differ by far more: the border fades, no seam shows.
TEST(Tints, BiomeBordersBlendWithoutASeam) {
  const TerrainGenerator gen(1, testing::defaultBlocks());
  const TintPalette maps = defaultPalette();
  constexpr int kChunks = 8;  // 128 x 128 columns
  const ChunkPos corner{kBorderChunkX, kBorderChunkZ};
  std::vector<glm::vec3> grass(kChunks * 16 * kChunks * 16);
  auto at = [&](int x, int z) -> glm::vec3& { return grass[static_cast<std::size_t>(z * kChunks * 16 + x)]; };
  bool biomes[kBiomeCount] = {};
  for (int cz = 0; cz < kChunks; ++cz)
    for (int cx = 0; cx < kChunks; ++cx) {
      Chunk chunk({corner.x + cx, corner.z + cz});
      gen.fillTints(chunk);
      for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) {
          at(cx * 16 + x, cz * 16 + z) = maps.colour(Tint::Grass, chunk.tint(x, z));
          biomes[static_cast<int>(gen.biomeAt(chunk.pos().minBlockX() + x, chunk.pos().minBlockZ() + z))] =
              true;
        }
    }
  ASSERT_TRUE(biomes[static_cast<int>(Biome::Desert)] && biomes[static_cast<int>(Biome::Forest)])
      << "the area holds the border it is meant to";
  float step = 0, range = 0;
  for (int z = 0; z < kChunks * 16; ++z)
    for (int x = 0; x < kChunks * 16; ++x) {
      if (x > 0) step = std::max(step, largestChannelStep(at(x, z), at(x - 1, z)));
      if (z > 0) step = std::max(step, largestChannelStep(at(x, z), at(x, z - 1)));
      range = std::max(range, largestChannelStep(at(x, z), at(0, 0)));
    }
  std::printf("largest step between neighbouring columns %.1f / 255, across the area %.1f / 255\n",
              step * 255.0f, range * 255.0f);
  EXPECT_LE(step, kBlendStepLimit);
  EXPECT_GT(range, 8.0f * kBlendStepLimit);
}

// Each tinted vertex carries its columns' colour: between column centres, interpolated; the mesher
// reads neighbouring chunks' columns at a chunk's edge. Untinted vertices carry none.
TEST(Tints, VerticesCarryTheirColumnsColourInterpolated) {
  const TintPalette palette(gradientMap(), gradientMap());
  testing::MeshWorld w(BlockMeshTable(
      testing::defaultBlocks(), [](BlockId, int) { return std::uint16_t{1}; }, {}, {}, {}, palette));
  w.set({5, 64, 5}, "grass_block");
  w.set({5, 65, 5}, "oak_leaves");
  int uniform = 0;
  for (const MeshData& layer : w.mesh().layers)
    for (const PackedVertex& v : layer.vertices) {
      if (v.tint() == 0) continue;
      ++uniform;
      EXPECT_EQ(v.tintRgb(), palette.rgb(Tint::Foliage)) << "one biome all round: its colour everywhere";
    }
  EXPECT_EQ(uniform, 4 * 6) << "the leaves' six faces (the grass top is hidden)";
  w.set({5, 64, 5}, "air");
  w.set({5, 65, 5}, "air");

  const ColumnTint warm = climateOnly({200, 40}), cold = climateOnly({40, 20});
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) w.world.chunk({0, 0})->setTint(x, z, x < 8 ? warm : cold);
  for (int z = 0; z < 16; ++z) {
    w.world.chunk({1, 0})->setTint(0, z, warm);
    w.world.chunk({-1, 0})->setTint(15, z, warm);
  }
  for (int x = 0; x < 16; ++x) w.set({x, 64, 3}, "grass_block");
  w.set({3, 64, 8}, "stone");
  const SectionMesh mesh = w.mesh({0, sectionOf(64), 0});
  int tops = 0;
  for (const PackedVertex& v : mesh.layers[static_cast<std::size_t>(MeshLayer::Opaque)].vertices) {
    if (v.tint() == 0) {
      EXPECT_EQ(v.tintRgb(), glm::u8vec3(0));
      continue;
    }
    ASSERT_EQ(v.face(), static_cast<int>(Direction::Up));
    ++tops;
    const int x32 = v.x32();
    // Corners at x = 0..7 lie between warm columns, x = 8 between warm and cold, 9..15 between cold
    // ones, x = 16 between this chunk's cold column 15 and the east chunk's warm column 0. The map's
    // texel is (255 - temperature, 255 - downfall, 7).
    const glm::u8vec3 expected = x32 < 8 * 32                    ? glm::u8vec3(55, 215, 7)
                                 : x32 > 8 * 32 && x32 < 16 * 32 ? glm::u8vec3(215, 235, 7)
                                                                 : glm::u8vec3(135, 225, 7);
    EXPECT_EQ(v.tintRgb(), expected) << "corner x = " << x32 / 32;
  }
  EXPECT_GT(tops, 0);
}

// A chunk read back from a save gets its generator's tints again (they are not saved).
TEST(Tints, ALoadedChunkGetsItsTintsBack) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  const TerrainGenerator gen(1, blocks);
  const ChunkPos pos{kBorderChunkX, kBorderChunkZ};
  Chunk generated(pos);
  gen.generate(generated);
  bool plainsOnly = true;
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) plainsOnly &= generated.tint(x, z) == kPlainsColumn;
  ASSERT_FALSE(plainsOnly) << "a chunk whose tints tell";
  const auto dir = testing::scratchDir("tints_saved");
  {
    WorldStorage storage(dir, blocks);
    generated.setModified(true);
    storage.save(generated);
    storage.flush();
  }
  WorldStorage storage(dir, blocks);
  ChunkLoader loader(gen, &storage, 1);
  loader.request(pos);
  std::vector<std::unique_ptr<Chunk>> done;
  for (int i = 0; i < 5000 && done.empty(); ++i) {
    done = loader.takeFinished();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(done.size(), 1u);
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(done[0]->tint(x, z), generated.tint(x, z));
}

}  // namespace
}  // namespace terrasol
