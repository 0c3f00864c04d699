// The streamed world pipeline: chunks generated or loaded around a centre, lit, meshed on workers
// once their neighbours are in, saved and reopened with their edits and their light.

#include "pipeline/streamed_world.h"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "core/error.h"
#include "support/streamed_world_support.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;
using testing::scratchDir;
using testing::settle;

TEST(StreamedWorldTest, EditsTheirLightTimeAndPlayerSurviveSavingAndReopening) {
  const auto dir = scratchDir("streamed_world");
  std::filesystem::remove_all(dir);
  const BlockMeshTable table(defaultBlocks(), [](BlockId, int) { return std::uint16_t(0); });
  const BlockId torch = defaultBlocks().id("torch");
  BlockPos broken, placed;
  std::vector<std::uint8_t> lightBefore;
  const auto lightAround = [](const StreamedWorld& w, BlockPos at) {
    std::vector<std::uint8_t> out;
    for (int dz = -3; dz <= 3; ++dz)
      for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx)
          out.push_back(w.light().lightAt(at.offset(dx, dy, dz), LightChannel::Block));
    return out;
  };
  {
    StreamedWorld w(dir, 42, defaultBlocks(), table, 2, 2);
    EXPECT_TRUE(w.isNew());
    settle(w);
    const auto y = w.surfaceY(3, 3);
    ASSERT_TRUE(y);
    broken = {3, *y, 3};
    placed = {5, *y + 1, 3};
    ASSERT_TRUE(w.setBlock(broken, kAir));
    w.setBlock(placed, kAir);
    ASSERT_TRUE(w.setBlock(placed, torch));
    EXPECT_EQ(w.light().lightAt(placed, LightChannel::Block), 14);
    lightBefore = lightAround(w, placed);
    w.level().time = 12345;
    w.level().playerPosition = {1.5, 90.0, 2.5};
    w.level().playerYaw = 33.0f;
    w.save();
  }
  StreamedWorld w(dir, 7, defaultBlocks(), table, 2, 2);
  EXPECT_FALSE(w.isNew());
  EXPECT_EQ(w.level().seed, 42u) << "an existing world keeps its seed";
  EXPECT_EQ(w.level().time, 12345);
  EXPECT_EQ(w.level().playerPosition, glm::dvec3(1.5, 90.0, 2.5));
  EXPECT_EQ(w.level().playerYaw, 33.0f);
  settle(w);
  EXPECT_EQ(w.world().getBlock(broken), kAir);
  EXPECT_EQ(w.world().getBlock(placed), torch);
  EXPECT_EQ(w.light().lightAt(placed, LightChannel::Block), 14);
  EXPECT_EQ(lightAround(w, placed), lightBefore);
}

TEST(StreamedWorldTest, MeshesOnlyChunksWithAllNeighboursAndDropsThemWhenTheyLeave) {
  const auto dir = scratchDir("streamed_world_stream");
  std::filesystem::remove_all(dir);
  const BlockMeshTable table(defaultBlocks(), [](BlockId, int) { return std::uint16_t(0); });
  StreamedWorld w(dir, 1, defaultBlocks(), table, 2, 2);
  settle(w);
  EXPECT_EQ(w.counts().loaded, 49u);    // view distance 2 + 1 ring: 7 x 7
  EXPECT_EQ(w.counts().meshable, 25u);  // the inner 5 x 5
  w.setViewDistance(0);                 // loads 1 ring, unloads beyond 2
  std::vector<SectionMesh> out = w.update({0, 0}, std::chrono::steady_clock::now());
  EXPECT_EQ(w.counts().loaded, 25u);
  EXPECT_EQ(w.counts().meshable, 9u);
  std::size_t removed = 0;
  for (const SectionMesh& m : out) removed += m.empty() && (std::abs(m.pos.x) == 2 || std::abs(m.pos.z) == 2);
  EXPECT_EQ(removed, 16u * kSectionCount);
}

TEST(StreamedWorldTest, AMalformedLevelFileIsAClearErrorAndIsNotOverwritten) {
  const auto dir = scratchDir("streamed_world_bad");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "level.json") << "{ \"seed\": "; }
  const BlockMeshTable table(defaultBlocks(), [](BlockId, int) { return std::uint16_t(0); });
  try {
    StreamedWorld w(dir, 1, defaultBlocks(), table, 2, 1);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("level.json"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readTextFile(dir / "level.json"), "{ \"seed\": ");
}

}  // namespace
}  // namespace terrasol
