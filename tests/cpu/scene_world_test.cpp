#include "scene/scene_world.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

SceneFile flatScene() {
  SceneFile scene = parseScene(R"({ "world": { "generator": "flat" }, "render": { "view_distance": 1 },
                                    "camera": { "position": [0, 70, 0], "look_at": [0, 64, -5] } })",
                               "test.json");
  return scene;
}

TEST(SceneWorld, EditsAreAppliedAndLitBeforeDrawing) {
  SceneFile scene = flatScene();
  scene.edits.push_back({SceneEdit::Kind::Fill, {-3, 64, -3}, {3, 66, 3}, "stone", "world.edits[0]"});
  scene.edits.push_back({SceneEdit::Kind::Fill, {-2, 64, -2}, {2, 65, 2}, "air", "world.edits[1]"});
  scene.edits.push_back({SceneEdit::Kind::Set, {0, 64, 0}, {0, 64, 0}, "torch", "world.edits[2]"});
  SceneWorld world(scene, defaultBlocks());
  EXPECT_EQ(world.world().getBlock({0, 64, 0}), defaultBlocks().id("torch"));
  EXPECT_EQ(world.world().getBlock({3, 66, 3}), defaultBlocks().id("stone"));
  EXPECT_EQ(world.light().lightAt({0, 64, 0}, LightChannel::Block), 14);
  EXPECT_EQ(world.light().lightAt({2, 64, 0}, LightChannel::Block), 12);
  EXPECT_EQ(world.light().lightAt({0, 65, 0}, LightChannel::Sky), 0) << "a sealed room gets no sky light";
  EXPECT_EQ(world.light().lightAt({0, 67, 0}, LightChannel::Sky), 15);
}

TEST(SceneWorld, LoadsOneRingMoreThanItMeshes) {
  SceneFile scene = flatScene();
  SceneWorld world(scene, defaultBlocks());
  EXPECT_EQ(world.world().chunkCount(), 25u);
  const BlockMeshTable table(defaultBlocks(), [](BlockId, int) { return std::uint16_t{0}; });
  for (const auto& mesh : world.meshVisible(table)) {
    EXPECT_LE(std::abs(mesh.pos.x), 1);
    EXPECT_LE(std::abs(mesh.pos.z), 1);
  }
}

TEST(SceneWorld, AHugeFillOnlyVisitsTheLoadedArea) {
  SceneFile scene = flatScene();
  scene.edits.push_back({SceneEdit::Kind::Fill,
                         {-2000000000, -64, -2000000000},
                         {2000000000, 63, 2000000000},
                         "air",
                         "world.edits[0]"});
  SceneWorld world(scene, defaultBlocks());
  EXPECT_EQ(world.world().getBlock({40, 10, 40}), kAir);
}

TEST(SceneWorld, AnUnknownBlockNamesTheEditKey) {
  SceneFile scene = flatScene();
  scene.edits.push_back({SceneEdit::Kind::Set, {0, 64, 0}, {0, 64, 0}, "unobtainium", "world.edits[3]"});
  try {
    SceneWorld world(scene, defaultBlocks());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: world.edits[3].block: unknown block 'unobtainium'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace terrasol
