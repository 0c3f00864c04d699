// The cloud layer: where it lies at a tick (exact for any tick, moving west), the map read from the
// pack stack (the topmost pack's, an unreadable one reported), and the default pack's generated map.
#include "core/cloud_layer.h"

#include <gtest/gtest.h>

#include "assets/cloud_map.h"
#include "core/paths.h"
#include "packgen.h"
#include "support/pack_builder.h"

namespace terrasol {
namespace {

TEST(CloudLayer, DriftsThreeBlocksWestEveryHundredTicksExactlyForAnyTick) {
  EXPECT_EQ(cloudDrift(0, 256), 0.0);
  EXPECT_EQ(cloudDrift(100, 256), 3.0);
  const std::int64_t cycle = 256 * 12 * 100 / 3;  // the map's 3072 blocks at 0.03 a tick
  EXPECT_EQ(cloudDrift(cycle, 256), 0.0);
  EXPECT_EQ(cloudDrift(cycle * 1'000'000'000 + 100, 256), 3.0) << "no precision lost to a world's age";
  EXPECT_EQ(cloudDrift(-100, 256), 256 * 12 - 3.0) << "before tick 0 it lay east";

  // One cloud texel in a 4 x 4 map: column (1, 2), blocks x 12..24, z 24..36 at tick 0.
  CloudMap map{4, 4, std::vector<std::uint8_t>(16, 0)};
  map.cover[2 * 4 + 1] = 255;
  EXPECT_TRUE(cloudCovers(map, 12.0, 24.0, 0));
  EXPECT_FALSE(cloudCovers(map, 11.9, 24.0, 0));
  EXPECT_FALSE(cloudCovers(map, 12.0, 36.0, 0));
  EXPECT_TRUE(cloudCovers(map, 12.0 + 48.0, 24.0 - 48.0, 0)) << "the map repeats";
  EXPECT_TRUE(cloudCovers(map, 9.0, 24.0, 100)) << "100 ticks later it lies 3 blocks west";
  EXPECT_FALSE(cloudCovers(map, 21.5, 24.0, 100));
  EXPECT_FALSE(cloudCovers(CloudMap{}, 0.0, 0.0, 0)) << "no map, no clouds";
}

TEST(CloudLayer, MapComesFromTheTopmostPackAndAnUnreadableOneIsReported) {
  std::vector<PackProblem> problems;
  const auto defaultPack = resourcePackDir() / "default";
  const CloudMap standard = loadCloudMap(testing::stackOf({defaultPack}), problems);
  EXPECT_TRUE(problems.empty());
  ASSERT_EQ(standard.width, 256);
  ASSERT_EQ(standard.height, 256);
  std::size_t covered = 0;
  for (const std::uint8_t c : standard.cover) covered += c >= 128 ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(covered) / static_cast<double>(standard.cover.size()), 0.35, 0.01);

  testing::PackBuilder pack("pack_clouds");
  EXPECT_EQ(loadCloudMap(testing::stackOf({defaultPack, pack.dir()}), problems).cover, standard.cover)
      << "a pack without clouds.png leaves the one below";
  Image own(2, 1);
  own.pixel(1, 0)[3] = 255;
  const auto environment = pack.dir() / "assets" / "minecraft" / "textures" / "environment";
  std::filesystem::create_directories(environment);
  saveImage(environment / "clouds.png", own);
  const CloudMap replaced = loadCloudMap(testing::stackOf({defaultPack, pack.dir()}), problems);
  EXPECT_EQ(replaced.width, 2);
  EXPECT_EQ(replaced.cover, (std::vector<std::uint8_t>{0, 255})) << "alpha is the coverage";
  EXPECT_TRUE(problems.empty());

  pack.asset("textures/environment/clouds.png", "not a png");
  EXPECT_TRUE(loadCloudMap(testing::stackOf({defaultPack, pack.dir()}), problems).empty());
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("clouds.png"), std::string::npos) << problems[0].message;
}

TEST(CloudLayer, DefaultPackMapIsWhatTheGeneratorMakesAndRepeatsSmoothly) {
  const Image generated = packgen::generateClouds();
  const Image committed = loadImage(resourcePackDir() / "default" / "assets" / "minecraft" / "textures" /
                                    "environment" / "clouds.png");
  EXPECT_EQ(committed.rgba, generated.rgba);
  // Across the map's edge cover changes no more often than inside it: the layer shows no seam.
  auto changes = [&](int from, int to) {
    int n = 0;
    for (int z = 0; z < 256; ++z) n += (generated.pixel(from, z)[3] != generated.pixel(to, z)[3]) ? 1 : 0;
    return n;
  };
  int inside = 0;
  for (int x = 0; x < 255; ++x) inside += changes(x, x + 1);
  EXPECT_LE(changes(255, 0), 2 * inside / 255 + 4);
}

}  // namespace
}  // namespace terrasol
