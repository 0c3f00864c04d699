// Biome tints: the colormaps' lookup, the default pack's maps, the blend across biome borders, the
// climate each vertex carries, and a loaded chunk getting its tints back.
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

PackStack stackOf(std::initializer_list<std::filesystem::path> dirs) {
  PackStack stack;
  for (const auto& d : dirs) stack.push(ResourcePack::open(d));
  return stack;
}

BiomeColormaps defaultColormaps() {
  std::vector<PackProblem> problems;
  BiomeColormaps maps = loadColormaps(stackOf({resourcePackDir() / "default"}), problems);
  EXPECT_TRUE(problems.empty());
  return maps;
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
  Image map(256, 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      std::uint8_t* p = map.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x), p[1] = static_cast<std::uint8_t>(y), p[2] = 7, p[3] = 255;
    }
  // x = (int)((1 - 0.8f) * 255) = 50 (0.8f is a little above 0.8, as in Minecraft), y = (int)(0.68 * 255) =
  // 173
  const glm::vec3 plains = sampleColormap(map, 0.8f, 0.4f);
  EXPECT_NEAR(plains.r * 255.0f, 50.0f, 0.5f);
  EXPECT_NEAR(plains.g * 255.0f, 173.0f, 0.5f);
  const glm::vec3 extreme = sampleColormap(map, 5.0f, -3.0f);  // clamped, never outside the map
  EXPECT_NEAR(extreme.r, 0.0f, 1e-6f);
  // The tint climate names the same texel, and tintColour reads it.
  EXPECT_EQ(kPlainsTint, (TintClimate{255 - 50, 255 - 173}));
  const BiomeColormaps maps{map, map};
  EXPECT_EQ(tintColour(maps, Tint::Grass, kPlainsTint) * 255.0f, glm::vec3(50, 173, 7));
  EXPECT_EQ(tintColour(maps, Tint::Foliage, tintClimate(5.0f, -3.0f)) * 255.0f, glm::vec3(0, 255, 7));
  EXPECT_EQ(tintColour(maps, Tint::None, kPlainsTint), glm::vec3(1.0f));

  testing::PackBuilder pack("pack_tints");
  std::vector<PackProblem> problems;
  const BiomeColormaps none = loadColormaps(stackOf({pack.dir()}), problems);
  EXPECT_LT(largestChannelStep(tintColour(none, Tint::Grass), kDefaultGrass), 0.5f / 255.0f);
  EXPECT_LT(largestChannelStep(tintColour(none, Tint::Foliage, tintClimate(2.0f, 0.0f)), kDefaultFoliage),
            0.5f / 255.0f)
      << "without a colormap every climate gets Minecraft's default";
  pack.asset("textures/colormap/grass.png", "not a png");
  loadColormaps(stackOf({pack.dir()}), problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("grass.png"), std::string::npos) << problems[0].message;
  problems.clear();
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const BiomeColormaps real =
      loadColormaps(stackOf({testing::testData() / "packs" / "pixel_perfection_ce"}), problems);
  EXPECT_TRUE(problems.empty());
  const glm::vec3 grass = tintColour(real, Tint::Grass);
  EXPECT_GT(largestChannelStep(grass, kDefaultGrass), 1.0f / 255.0f)
      << "pixel_perfection_ce's grass colormap is used";
  EXPECT_GT(grass.g, grass.b) << "and it is green";
}

// The default pack ships colormaps whose plains texels are Minecraft's plains colours; other climates
// move the way Minecraft's maps do. The committed maps are what the pack generator makes.
TEST(Tints, DefaultPackColormapsGiveMinecraftsColours) {
  const BiomeColormaps maps = defaultColormaps();
  ASSERT_EQ(maps.grass.width, 256);
  EXPECT_LT(largestChannelStep(tintColour(maps, Tint::Grass), kDefaultGrass), 1.5f / 255.0f);
  EXPECT_LT(largestChannelStep(tintColour(maps, Tint::Foliage), kDefaultFoliage), 1.5f / 255.0f);
  const glm::vec3 desert = tintColour(maps, Tint::Grass, biomeTint(Biome::Desert));
  const glm::vec3 forest = tintColour(maps, Tint::Grass, biomeTint(Biome::Forest));
  const glm::vec3 snowy = tintColour(maps, Tint::Grass, biomeTint(Biome::SnowyPlains));
  EXPECT_GT(desert.r, forest.r + 0.2f) << "dry heat yellows the grass";
  EXPECT_GT(snowy.b, forest.b + 0.15f) << "cold blues it";
  EXPECT_EQ(tintColour(maps, Tint::Birch, biomeTint(Biome::Desert)), kBirchFoliage)
      << "fixed, whatever the biome";
  EXPECT_EQ(tintColour(maps, Tint::Spruce, biomeTint(Biome::Taiga)), kSpruceFoliage);

  for (const auto& c : packgen::generateColormaps()) {
    const Image committed = loadImage(resourcePackDir() / "default" / "assets" / "minecraft" / "textures" /
                                      "colormap" / (c.name + ".png"));
    EXPECT_EQ(committed.rgba, c.map.rgba) << c.name;
  }
}

TEST(Tints, WaterIsBluerInTheColdAndTurquoiseInTheHeat) {
  const BiomeColormaps maps = defaultColormaps();
  EXPECT_EQ(tintColour(maps, Tint::Water, biomeTint(Biome::Plains)), kWaterTemperate);
  EXPECT_EQ(tintColour(maps, Tint::Water, biomeTint(Biome::Ocean)), kWaterTemperate);
  EXPECT_EQ(tintColour(maps, Tint::Water, biomeTint(Biome::SnowyPlains)), kWaterCold);
  EXPECT_EQ(tintColour(maps, Tint::Water, biomeTint(Biome::Desert)), kWaterWarm);
  const glm::vec3 taiga = tintColour(maps, Tint::Water, biomeTint(Biome::Taiga));
  EXPECT_GT(taiga.g, kWaterCold.g);
  EXPECT_LT(taiga.g, kWaterTemperate.g);
}

// Across a border between forest and desert, neighbouring columns' grass differs by at most a few
// levels, while the two sides differ by far more: the border fades, no seam shows.
TEST(Tints, BiomeBordersBlendWithoutASeam) {
  const TerrainGenerator gen(1, testing::defaultBlocks());
  const BiomeColormaps maps = defaultColormaps();
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
          at(cx * 16 + x, cz * 16 + z) = tintColour(maps, Tint::Grass, chunk.tint(x, z));
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

// Each tinted vertex carries the climate at its position: between column centres, interpolated; the
// mesher reads neighbouring chunks' columns at a chunk's edge. Untinted vertices carry none.
TEST(Tints, VerticesCarryTheirColumnsClimateInterpolated) {
  testing::MeshWorld w(
      BlockMeshTable(testing::defaultBlocks(), [](BlockId, int) { return std::uint16_t{1}; }));
  w.set({5, 64, 5}, "grass_block");
  w.set({5, 65, 5}, "oak_leaves");
  int uniform = 0;
  for (const MeshData& layer : w.mesh().layers)
    for (const PackedVertex& v : layer.vertices) {
      if (v.tint() == 0) continue;
      ++uniform;
      EXPECT_EQ(v.tintTemperature(), kPlainsTint.temperature)
          << "one biome all round: its climate everywhere";
      EXPECT_EQ(v.tintDownfall(), kPlainsTint.downfall);
    }
  EXPECT_EQ(uniform, 4 * 6) << "the leaves' six faces (the grass top is hidden)";
  w.set({5, 64, 5}, "air");
  w.set({5, 65, 5}, "air");

  const TintClimate warm{200, 40}, cold{40, 20};
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
      EXPECT_EQ(v.tintTemperature(), 0);
      EXPECT_EQ(v.tintDownfall(), 0);
      continue;
    }
    ASSERT_EQ(v.face(), static_cast<int>(Direction::Up));
    ++tops;
    const int x32 = v.x32();
    // Corners at x = 0..7 lie between warm columns, x = 8 between warm and cold, 9..15 between cold
    // ones, x = 16 between this chunk's cold column 15 and the east chunk's warm column 0.
    const TintClimate expected = x32 < 8 * 32                    ? warm
                                 : x32 > 8 * 32 && x32 < 16 * 32 ? cold
                                                                 : TintClimate{120, 30};
    EXPECT_EQ(v.tintTemperature(), expected.temperature) << "corner x = " << x32 / 32;
    EXPECT_EQ(v.tintDownfall(), expected.downfall) << "corner x = " << x32 / 32;
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
    for (int x = 0; x < 16; ++x) plainsOnly &= generated.tint(x, z) == kPlainsTint;
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
