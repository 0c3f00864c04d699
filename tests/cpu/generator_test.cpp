#include "world/generator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "core/error.h"
#include "support/world_support.h"
#include "world/biomes.h"
#include "world/chunk_loader.h"
#include "world/terrain_generator.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;
using testing::sameBlocks;

std::unique_ptr<Chunk> generate(const ChunkGenerator& g, ChunkPos pos) {
  auto chunk = std::make_unique<Chunk>(pos);
  g.generate(*chunk);
  return chunk;
}

TEST(FlatGenerator, DefaultLayersPutTheGrassAtY63AndCostLittleMemory) {
  const BlockRegistry& b = defaultBlocks();
  const auto gen = makeGenerator({"flat", 0, {}}, b);
  const auto chunk = generate(*gen, {-3, 7});
  EXPECT_EQ(chunk->get(0, -1, 0), kAir);
  EXPECT_EQ(chunk->get(4, 0, 9), b.id("bedrock"));
  EXPECT_EQ(chunk->get(4, 1, 9), b.id("stone"));
  EXPECT_EQ(chunk->get(4, 59, 9), b.id("stone"));
  EXPECT_EQ(chunk->get(4, 60, 9), b.id("dirt"));
  EXPECT_EQ(chunk->get(4, 62, 9), b.id("dirt"));
  EXPECT_EQ(chunk->get(15, 63, 15), b.id("grass_block"));
  EXPECT_EQ(chunk->get(15, 64, 15), kAir);
  EXPECT_EQ(gen->surfaceHeight(0, 0), 63);
  // Sections y 16..31 and 32..47 are all stone: uniform, no arrays. Only y 0..15 and 48..63 are mixed.
  EXPECT_EQ(chunk->memoryBytes(), sizeof(Chunk) + 2 * 8192u);
}

TEST(FlatGenerator, LayerStringsParseLikeMinecraftsAndBadOnesAreNamed) {
  const BlockRegistry& b = defaultBlocks();
  const auto layers = parseFlatLayers("minecraft:bedrock,2*dirt,sand", b);
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers[1].thickness, 2);
  EXPECT_EQ(layers[2].block, b.id("sand"));
  auto error = [&](const std::string& s) {
    try {
      parseFlatLayers(s, b);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("bedrock,3*diamond").find("unknown block 'diamond'"), std::string::npos);
  EXPECT_NE(error("0*stone").find("COUNT >= 1"), std::string::npos);
  EXPECT_NE(error("x*stone").find("entry 'x*stone'"), std::string::npos);
  EXPECT_NE(error("400*stone").find("above the world top"), std::string::npos);
  EXPECT_THROW(makeGenerator({"moon", 0, {}}, b), Error);
}

TEST(VoidGenerator, IsAllAir) {
  const auto chunk = generate(*makeGenerator({"void", 0, {}}, defaultBlocks()), {5, 5});
  EXPECT_EQ(chunk->memoryBytes(), sizeof(Chunk));
}

TEST(TerrainGenerator, SameSeedSameBlocksDifferentSeedDifferentBlocks) {
  const auto a = makeGenerator({"terrain", 42, {}}, defaultBlocks());
  const auto b = makeGenerator({"terrain", 42, {}}, defaultBlocks());
  const auto c = makeGenerator({"terrain", 43, {}}, defaultBlocks());
  for (ChunkPos p : {ChunkPos{0, 0}, ChunkPos{-7, 3}, ChunkPos{100, -250}}) {
    EXPECT_TRUE(sameBlocks(*generate(*a, p), *generate(*b, p)));
    EXPECT_FALSE(sameBlocks(*generate(*a, p), *generate(*c, p)));
  }
}

// The loader's workers must produce exactly what a single thread does, whatever their number and
// order (trees cross chunk borders, so this also checks features are order-independent).
TEST(TerrainGenerator, ThreadCountDoesNotChangeTheWorld) {
  const auto gen = makeGenerator({"terrain", 7, {}}, defaultBlocks());
  std::vector<ChunkPos> positions;
  for (int z = -3; z <= 3; ++z)
    for (int x = -3; x <= 3; ++x) positions.push_back({x, z});
  std::map<std::pair<int, int>, std::unique_ptr<Chunk>> reference;
  for (ChunkPos p : positions) reference[{p.x, p.z}] = generate(*gen, p);

  for (int threads : {1, 2, 4}) {
    ChunkLoader loader(*gen, nullptr, threads);
    loader.setCenter({3, -3});  // a different order for every thread count
    for (ChunkPos p : positions) loader.request(p);
    std::size_t received = 0;
    while (received < positions.size()) {
      for (auto& chunk : loader.takeFinished()) {
        EXPECT_TRUE(sameBlocks(*chunk, *reference[{chunk->pos().x, chunk->pos().z}]))
            << threads << " threads, chunk " << chunk->pos().x << "," << chunk->pos().z;
        ++received;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_EQ(loader.pending(), 0u);
  }
}

// Counts every block kind over an area, so the features the issue asks for are known to appear.
std::map<std::string, int> census(const ChunkGenerator& gen, int cx0, int cz0, int n) {
  std::map<std::string, int> counts;
  const BlockRegistry& b = defaultBlocks();
  for (int cz = cz0; cz < cz0 + n; ++cz)
    for (int cx = cx0; cx < cx0 + n; ++cx) {
      const auto chunk = generate(gen, {cx, cz});
      for (int y = kMinY; y < kMaxY; ++y)
        for (int z = 0; z < 16; ++z)
          for (int x = 0; x < 16; ++x) {
            const BlockId id = chunk->get(x, y, z);
            // Air below the surface is cave.
            const bool cave = id == kAir && y < gen.surfaceHeight(cx * 16 + x, cz * 16 + z) - 1;
            ++counts[cave ? "cave air" : b[id].name];
          }
    }
  return counts;
}

TEST(TerrainGenerator, HasEveryFeatureOfAMinecraftLikeWorld) {
  const auto gen = makeGenerator({"terrain", 1, {}}, defaultBlocks());
  const auto counts = census(*gen, -8, -8, 16);  // 256 x 256 blocks
  for (const char* name : {"stone",
                           "dirt",
                           "grass_block",
                           "sand",
                           "water",
                           "bedrock",
                           "oak_log",
                           "oak_leaves",
                           "short_grass",
                           "dandelion",
                           "poppy",
                           "coal_ore",
                           "iron_ore",
                           "gold_ore",
                           "lava",
                           "glowstone",
                           "cave air",
                           "deepslate",
                           "deepslate_iron_ore",
                           "copper_ore",
                           "lapis_ore",
                           "deepslate_diamond_ore"}) {
    EXPECT_GT(counts.count(name) ? counts.at(name) : 0, 0) << name << " never generated";
  }
  // Heights cover sea, plains and mountains somewhere in a wider sample.
  int lowest = kMaxY, highest = kMinY;
  for (int z = -2000; z <= 2000; z += 50)
    for (int x = -2000; x <= 2000; x += 50) {
      lowest = std::min(lowest, gen->surfaceHeight(x, z));
      highest = std::max(highest, gen->surfaceHeight(x, z));
    }
  EXPECT_LT(lowest, TerrainGenerator::kSeaLevel - 10);
  EXPECT_GT(highest, 140);
}

// Deepslate fills the ground below y = 0 and thins out up to y = 7; ores follow their depths: each
// kind in the rock it lies in, diamonds only up to y = 16.
TEST(TerrainGenerator, DeepslateBelowZeroAndOresByDepth) {
  const auto gen = makeGenerator({"terrain", 1, {}}, defaultBlocks());
  const BlockRegistry& b = defaultBlocks();
  std::map<int, std::pair<int, int>> rock;  // y: stone, deepslate
  int diamondsHigh = 0, stoneOresDeep = 0, deepOresHigh = 0;
  for (int cz = -3; cz < 3; ++cz)
    for (int cx = -3; cx < 3; ++cx) {
      const auto chunk = generate(*gen, {cx, cz});
      for (int y = -40; y < 40; ++y)
        for (int z = 0; z < 16; ++z)
          for (int x = 0; x < 16; ++x) {
            const std::string& name = b[chunk->get(x, y, z)].name;
            if (name == "stone") ++rock[y].first;
            if (name == "deepslate") ++rock[y].second;
            if (name.find("diamond_ore") != std::string::npos && y > 16)
              ++diamondsHigh;  // veins start below 16
            if (name.ends_with("_ore") && !name.starts_with("deepslate") && name != "emerald_ore" && y < 0)
              ++stoneOresDeep;
            if (name.starts_with("deepslate_") && name.ends_with("_ore") && y >= 8) ++deepOresHigh;
          }
    }
  for (const auto& [y, counts] : rock) {
    if (y < 0) {
      EXPECT_EQ(counts.first, 0) << "stone at y " << y;
    }
    if (y >= 8) {
      EXPECT_EQ(counts.second, 0) << "deepslate at y " << y;
    }
  }
  EXPECT_GT(rock[3].first, 0);
  EXPECT_GT(rock[3].second, 0) << "a blend at y 3";
  EXPECT_GT(rock[1].second, rock[6].second) << "thinning out upwards";
  EXPECT_EQ(diamondsHigh, 0);
  EXPECT_EQ(stoneOresDeep, 0);
  EXPECT_EQ(deepOresHigh, 0);
}

// Biomes come from the seed alone, every one of them lies within a few thousand blocks, and their
// borders are smooth: few columns have a neighbour of another biome.
TEST(Biomes, DeterministicEveryKindAndSmoothBorders) {
  const BiomeSource a(1), b(1), c(2);
  const TerrainGenerator gen(1, defaultBlocks());
  std::array<int, kBiomeCount> seen{};
  int differ = 0, borders = 0, columns = 0;
  for (int z = -3000; z <= 3000; z += 25)
    for (int x = -3000; x <= 3000; x += 25) {
      const int h = gen.surfaceHeight(x, z);
      ASSERT_EQ(a.biomeAt(x, z, h), b.biomeAt(x, z, h));
      differ += a.biomeAt(x, z, h) != c.biomeAt(x, z, h);
      const Biome here = gen.biomeAt(x, z);
      ++seen[static_cast<std::size_t>(here)];
      borders += gen.biomeAt(x + 1, z) != here || gen.biomeAt(x, z + 1) != here;
      ++columns;
    }
  for (int k = 0; k < kBiomeCount; ++k)
    EXPECT_GT(seen[static_cast<std::size_t>(k)], 50) << biomeName(static_cast<Biome>(k));
  EXPECT_GT(differ, columns / 5) << "another seed, other biomes";
  EXPECT_LT(borders, columns / 25) << "neighbouring columns of different biomes";
}

// Each biome's ground and growth: desert sand over sandstone with cacti and dead bushes, snow on
// the snowy plains with ice on their water, spruces in the taiga, birches in birch forests, acacias
// on the savanna.
TEST(Biomes, EachBiomeHasItsGroundAndTrees) {
  const TerrainGenerator gen(1, defaultBlocks());
  const BlockRegistry& b = defaultBlocks();
  std::map<std::string, std::set<std::string>> found;  // biome: blocks at and above its surfaces
  const auto sample = [&](Biome wanted) {
    // The first chunk, walking out from the origin, well inside the biome (inland, for the snow), and
    // its eight neighbours; only the biome's own columns count.
    const auto inside = [&](int x, int z) {
      for (const auto& [dx, dz] :
           {std::pair{0, 0}, std::pair{-40, 0}, std::pair{40, 0}, std::pair{0, -40}, std::pair{0, 40}}) {
        if (gen.biomeAt(x + dx, z + dz) != wanted ||
            gen.surfaceHeight(x + dx, z + dz) <= TerrainGenerator::kSeaLevel + 1)
          return false;
      }
      return true;
    };
    for (int r = 0; r < 300; ++r)
      for (int i = -r; i <= r; ++i)
        for (const auto& [cx, cz] : {std::pair{i, -r}, std::pair{i, r}, std::pair{-r, i}, std::pair{r, i}}) {
          if (!inside(cx * 16 + 8, cz * 16 + 8)) continue;
          for (int dz = -1; dz <= 1; ++dz)
            for (int dx = -1; dx <= 1; ++dx) {
              auto chunk = std::make_unique<Chunk>(ChunkPos{cx + dx, cz + dz});
              gen.generate(*chunk);
              for (int z = 0; z < 16; ++z)
                for (int x = 0; x < 16; ++x) {
                  const int wx = chunk->pos().minBlockX() + x, wz = chunk->pos().minBlockZ() + z;
                  if (gen.biomeAt(wx, wz) != wanted) continue;
                  const int h = gen.surfaceHeight(wx, wz);
                  for (int y = h - 6; y <= h + 12; ++y)
                    found[std::string(biomeName(wanted))].insert(b[chunk->get(x, y, z)].name);
                }
            }
          return;
        }
    ADD_FAILURE() << "no " << biomeName(wanted) << " near the origin";
  };
  for (const Biome biome :
       {Biome::Desert, Biome::SnowyPlains, Biome::Taiga, Biome::BirchForest, Biome::Savanna})
    sample(biome);
  const auto has = [&](const char* biome, const char* block) { return found[biome].contains(block); };
  EXPECT_TRUE(has("desert", "sand") && has("desert", "sandstone") && has("desert", "dead_bush") &&
              has("desert", "cactus"));
  EXPECT_FALSE(has("desert", "grass_block"));
  EXPECT_TRUE(has("snowy_plains", "snow") && has("snowy_plains", "spruce_log"));
  EXPECT_TRUE(has("taiga", "spruce_log") && has("taiga", "spruce_leaves") && has("taiga", "fern"));
  EXPECT_TRUE(has("birch_forest", "birch_log") && has("birch_forest", "birch_leaves"));
  EXPECT_TRUE(has("savanna", "acacia_log"));
}

TEST(TerrainGenerator, CavesOpenToTheSurfaceSomewhere) {
  const auto gen = makeGenerator({"terrain", 1, {}}, defaultBlocks());
  const TerrainGenerator& terrain = static_cast<const TerrainGenerator&>(*gen);
  int openings = 0;
  for (int z = -512; z < 512; z += 2)
    for (int x = -512; x < 512; x += 2) {
      const int h = gen->surfaceHeight(x, z);
      if (h > TerrainGenerator::kSeaLevel + 2 && terrain.caveDensity(x, h, z) < 0.0) ++openings;
    }
  EXPECT_GT(openings, 10);
}

TEST(TerrainGenerator, FarAwayTerrainIsAsSmoothAsAtTheOrigin) {
  const auto gen = makeGenerator({"terrain", 3, {}}, defaultBlocks());
  auto maxStep = [&](int x0, int z0) {
    int step = 0;
    for (int i = 0; i < 2000; ++i) {
      step = std::max(step, std::abs(gen->surfaceHeight(x0 + i + 1, z0) - gen->surfaceHeight(x0 + i, z0)));
    }
    return step;
  };
  const int near = maxStep(0, 0), far = maxStep(29'997'000, 29'999'000);
  EXPECT_LE(far, std::max(near, 6)) << "terrain far away must not become jagged (float precision)";
  EXPECT_GT(far, 0) << "terrain far away must not become flat";
  const auto chunk = generate(*gen, ChunkPos::of({29'999'000, 0, 29'999'000}));
  EXPECT_EQ(chunk->get(0, kMinY, 0), defaultBlocks().id("bedrock"));
}

}  // namespace
}  // namespace terrasol
