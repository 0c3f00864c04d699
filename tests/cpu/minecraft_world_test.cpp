// A Minecraft save as a world: the game's overlay (edits kept beside the game's worlds, the save never
// written), scene files naming a save, and the player's start.

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "core/error.h"
#include "light_compare.h"
#include "pipeline/streamed_world.h"
#include "scene/scene_file.h"
#include "scene/scene_world.h"
#include "support/anvil_writer.h"
#include "support/streamed_world_support.h"
#include "support/test_data.h"
#include "support/world_support.h"
#include "world_choice.h"

namespace terrasol {
namespace {

using namespace testing;

constexpr int kV1_20_6 = 3839;

// A save of 3 x 3 chunks round the origin: stone from y = -64 to 63 (one-entry palettes, no data), a
// layer of grass blocks at y = 64 over (0..15, 0..15) only, and a level.dat whose player stands at
// (1.5, 65, -2.5).
std::filesystem::path writeSave(const std::string& name) {
  const auto dir = scratchDir(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<RegionEntry> byRegion[4];
  for (int cz = -1; cz <= 1; ++cz)
    for (int cx = -1; cx <= 1; ++cx) {
      std::vector<TestSection> sections;
      for (int y = -4; y < 4; ++y) sections.push_back({.y = y, .palette = {"stone"}, .indices = {}});
      if (cx == 0 && cz == 0) {
        TestSection grass{.y = 4, .palette = {"air", "grass_block[snowy=false]"}, .indices = {}};
        grass.indices.assign(4096, 0);
        for (int i = 0; i < 256; ++i) grass.indices[static_cast<std::size_t>(i)] = 1;
        sections.push_back(grass);
      }
      const ChunkPos pos{cx, cz};
      byRegion[(cx < 0 ? 0 : 1) + (cz < 0 ? 0 : 2)].push_back(
          {pos, encodeNbt(chunkNbt(kV1_20_6, pos, sections)), TestCompression::Zlib});
    }
  for (const auto& entries : byRegion) writeRegion(dir / "region", entries);
  writeLevelDat(dir / "level.dat", kV1_20_6, "1.20.6");
  return dir;
}

std::map<std::filesystem::path, std::string> filesOf(const std::filesystem::path& dir) {
  std::map<std::filesystem::path, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    files[e.path()] = {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  return files;
}

TEST(MinecraftWorld, TheGameKeepsASavesEditsInAnOverlayBesideItsWorlds) {
  const auto save = writeSave("mc_overlay_save");
  const auto worlds = scratchDir("mc_overlay_worlds");
  std::filesystem::remove_all(worlds);
  const WorldChoice choice = chooseWorld(save, worlds);
  EXPECT_EQ(choice.minecraft, std::filesystem::absolute(save).lexically_normal());
  EXPECT_EQ(choice.dir.parent_path(), worlds);
  EXPECT_TRUE(choice.dir.filename().string().starts_with("minecraft-mc_overlay_save-"));
  EXPECT_EQ(chooseWorld(save, worlds).dir, choice.dir);  // the same save finds its overlay again
  EXPECT_EQ(chooseWorld(worlds / "world", worlds).dir, worlds / "world");  // a Terrasol world is itself
  EXPECT_TRUE(chooseWorld(worlds / "world", worlds).minecraft.empty());

  const auto before = filesOf(save);
  const BlockMeshTable table(defaultBlocks(), [](BlockId, int) { return std::uint16_t(0); });
  const BlockId grass = defaultBlocks().id("grass_block");
  {
    StreamedWorld w(choice.dir, 1, defaultBlocks(), table, 2, 2, nullptr, choice.minecraft);
    ASSERT_TRUE(w.minecraft());
    EXPECT_EQ(w.minecraft()->startPosition(), glm::dvec3(1.5, 65.0, -2.5));
    settle(w);
    EXPECT_EQ(w.world().getBlock({3, 64, 3}), grass);
    EXPECT_EQ(w.world().getBlock({3, 63, 3}), defaultBlocks().id("stone"));
    EXPECT_EQ(w.world().getBlock({-3, 64, 3}), kAir);
    EXPECT_EQ(w.surfaceY(3, 3), 64);
    ASSERT_TRUE(w.setBlock({3, 64, 3}, kAir));
    w.save();
  }
  {
    // Reopened without naming the save: its level.json does.
    StreamedWorld w(choice.dir, 1, defaultBlocks(), table, 2, 2);
    ASSERT_TRUE(w.minecraft());
    EXPECT_FALSE(w.isNew());
    settle(w);
    EXPECT_EQ(w.world().getBlock({3, 64, 3}), kAir);
    EXPECT_EQ(w.world().getBlock({4, 64, 3}), grass);
    // Chunks the save does not hold are empty, not generated.
    ASSERT_TRUE(w.world().isLoaded({2, 0}));
    EXPECT_EQ(w.world().getBlock({40, 0, 5}), kAir);
    EXPECT_EQ(w.world().getBlock({20, 0, 5}), defaultBlocks().id("stone"));
  }
  EXPECT_EQ(filesOf(save), before);
  EXPECT_TRUE(std::filesystem::exists(choice.dir / "level.json"));
}

TEST(MinecraftWorld, AScenesWorldMayBeASave) {
  const auto save = writeSave("mc_scene_save");
  const SceneFile scene = parseScene(R"({"world": {"minecraft": ")" + save.string() +
                                         R"(", "edits": [{"set": [2, 64, 2], "block": "glowstone"}]},
                                         "render": {"view_distance": 1}, "camera": {"position": [8, 70, 8], "look_at": [0, 64, 0]}})",
                                     "mc.json");
  EXPECT_EQ(scene.minecraftWorld, save);
  const SceneWorld world(scene, defaultBlocks());
  EXPECT_EQ(world.world().getBlock({2, 64, 2}), defaultBlocks().id("glowstone"));
  EXPECT_EQ(world.world().getBlock({5, 64, 5}), defaultBlocks().id("grass_block"));
  // A save is the world: a generator beside it, or a folder with no save, is an error naming the key.
  EXPECT_THROW(parseScene(R"({"world": {"minecraft": "x", "seed": 3}})", "mc.json"), Error);
  const SceneFile missing = parseScene(R"({"world": {"minecraft": "/nonexistent/save"}})", "mc.json");
  try {
    SceneWorld w(missing, defaultBlocks());
    ADD_FAILURE() << "opened";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("world.minecraft"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace terrasol

namespace terrasol {
namespace {

// The goal: Terrasol's light equals the light Minecraft stored in at least 99.9 % of the go-mc save's
// cells per channel (docs/world.md explains every cell that differs).
TEST(MinecraftWorld, TheGoMcSavesLightIsMinecraftsOwn) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const LightComparison c = compareLight(testData() / "worlds" / "go-mc-1.18.1", defaultBlocks());
  EXPECT_EQ(c.chunks, 495u);
  EXPECT_EQ(c.cells, 495u * 16u * 16u * 384u);
  EXPECT_GE(c.sky.equalPercent(c.cells), 99.999);
  EXPECT_GE(c.block.equalPercent(c.cells), 99.99);
  // Every block-light difference is Terrasol brighter beside a chunk border (the lichens' light
  // Minecraft stopped there).
  for (const LightDifference& d : c.samples) {
    const int x = d.pos.x & 15, z = d.pos.z & 15;
    EXPECT_TRUE(!d.sky && d.ours > d.theirs && (std::min(x, 15 - x) <= 4 || std::min(z, 15 - z) <= 4))
        << d.pos.x << " " << d.pos.y << " " << d.pos.z;
  }
}

}  // namespace
}  // namespace terrasol
