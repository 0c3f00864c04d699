#include "world/block_table.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/error_of.h"
#include "support/world_support.h"
#include "world/block_shapes.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

int emission(const char* state) {
  return defaultBlocks().emissions()[defaultBlocks().id(state)];
}
int opacity(const char* state) {
  return defaultBlocks().opacities()[defaultBlocks().id(state)];
}

// Minecraft 1.21.11's blocks, states numbered as Minecraft numbers them (minecraft-data's
// minStateId / defaultState), then the blocks the default pack adds.
TEST(BlockTable, EveryMinecraftBlockWithMinecraftsStateIds) {
  const BlockRegistry& b = defaultBlocks();
  EXPECT_EQ(b.minecraftBlockCount(), 1166u);
  EXPECT_GE(b.size(), 29671u);
  EXPECT_EQ(b.id("stone"), 1);
  EXPECT_EQ(b.id("oak_leaves"), 279) << "distance=7, persistent=false, waterlogged=false";
  EXPECT_EQ(b.stateName(279), "oak_leaves[distance=7,persistent=false,waterlogged=false]");
  EXPECT_EQ(b.id("oak_stairs"), 3717);
  EXPECT_EQ(b.id("candle"), 22897);
  EXPECT_EQ(b.id("oak_leaves[distance=1,persistent=true,waterlogged=true]"), 252);
  EXPECT_EQ(b.block(b.minecraftBlockCount() - 1).firstState + b.block(b.minecraftBlockCount() - 1).stateCount,
            29671);
  for (std::size_t i = 0; i < b.minecraftBlockCount(); ++i)
    EXPECT_TRUE(b.block(i).minecraft) << b.block(i).name;
}

// Light by state as Minecraft gives it: lit furnaces and lamps, candles by count, sea pickles in
// water only, the light block by level, respawn anchors by charge.
// A world from before Minecraft renamed a block still names it the old way: grass (short_grass since
// 1.20.3), chain (iron_chain since 1.21.9), grass_path (dirt_path since 1.17).
TEST(BlockTable, RenamedBlocksAreFoundByTheirOldNames) {
  const BlockRegistry& blocks = defaultBlocks();
  EXPECT_EQ(blocks.id("grass"), blocks.id("short_grass"));
  EXPECT_EQ(blocks.id("chain[axis=x,waterlogged=false]"), blocks.id("iron_chain[axis=x,waterlogged=false]"));
  EXPECT_EQ(blocks.id("grass_path"), blocks.id("dirt_path"));
  bool found = true;
  blocks.find("grassy", &found);
  EXPECT_FALSE(found);
}

TEST(BlockTable, LightFollowsTheState) {
  EXPECT_EQ(emission("furnace[lit=true]"), 13);
  EXPECT_EQ(emission("furnace[lit=false]"), 0);
  EXPECT_EQ(emission("redstone_lamp[lit=true]"), 15);
  EXPECT_EQ(emission("candle[candles=1,lit=true]"), 3);
  EXPECT_EQ(emission("candle[candles=4,lit=true]"), 12);
  EXPECT_EQ(emission("candle[candles=4,lit=false]"), 0);
  EXPECT_EQ(emission("sea_pickle[pickles=4,waterlogged=true]"), 15);
  EXPECT_EQ(emission("sea_pickle[pickles=4,waterlogged=false]"), 0);
  EXPECT_EQ(emission("light[level=9]"), 9);
  EXPECT_EQ(emission("respawn_anchor[charges=0]"), 0);
  EXPECT_EQ(emission("respawn_anchor[charges=2]"), 7);
  EXPECT_EQ(emission("respawn_anchor[charges=4]"), 15);
  EXPECT_EQ(emission("cave_vines[berries=true]"), 14);
  EXPECT_EQ(emission("weathered_copper_bulb[lit=true]"), 8);
  EXPECT_EQ(emission("torch"), 14);
  EXPECT_EQ(emission("lava"), 15);
  EXPECT_EQ(defaultBlocks()[defaultBlocks().id("light")].emission, 15) << "the default state's";
}

// A cell holds water beside its block where the block allows it: waterlogged states and blocks
// that always stand in water. Light passes it as through water.
TEST(BlockTable, WaterloggedStatesHoldWaterAndFilterLightAsWaterDoes) {
  const BlockRegistry& b = defaultBlocks();
  const auto water = [&](const char* s) { return b.holdsWater()[b.id(s)] == 1; };
  EXPECT_TRUE(water("oak_stairs[waterlogged=true]"));
  EXPECT_FALSE(water("oak_stairs[waterlogged=false]"));
  EXPECT_TRUE(water("seagrass"));
  EXPECT_TRUE(water("kelp"));
  EXPECT_FALSE(water("water")) << "water is the block itself";
  EXPECT_FALSE(water("stone"));
  EXPECT_EQ(opacity("glass_pane[waterlogged=true]"), opacity("water"));
  EXPECT_EQ(opacity("glass_pane[waterlogged=false]"), 0);
  EXPECT_EQ(opacity("lantern[waterlogged=true]"), 1);
  EXPECT_EQ(opacity("stone"), 15);
}

// Collision by state from the table: an open gate lets players through, snow layers rise by two
// sixteenths a layer (the first has none), fences stand a block and a half.
TEST(BlockTable, CollisionFollowsTheState) {
  const BlockRegistry& b = defaultBlocks();
  const BlockShapes shapes(b);
  const auto boxes = [&](const char* s) { return shapes.collision(b.id(s)); };
  EXPECT_TRUE(boxes("oak_fence_gate[open=true]").empty());
  EXPECT_FALSE(boxes("oak_fence_gate[open=false]").empty());
  EXPECT_TRUE(boxes("snow[layers=1]").empty());
  ASSERT_EQ(boxes("snow[layers=3]").size(), 1u);
  EXPECT_EQ(boxes("snow[layers=3]")[0].to[1], 4);
  ASSERT_FALSE(boxes("oak_fence").empty());
  EXPECT_EQ(boxes("oak_fence")[0].to[1], 24);
  EXPECT_EQ(boxes("stone"), std::vector<ShapeBox>{ShapeBox{}});
  EXPECT_TRUE(boxes("short_grass").empty());
  // Half sixteenths (an iron chain's 6.5 .. 9.5) round outward.
  ASSERT_EQ(boxes("iron_chain[axis=y]").size(), 1u);
  EXPECT_EQ(boxes("iron_chain[axis=y]")[0].from[0], 6);
  EXPECT_EQ(boxes("iron_chain[axis=y]")[0].to[0], 10);
}

// blocks.json gives Minecraft's blocks their looks and rules, never their facts: a restated fact is
// refused with the place it was written, so the two cannot disagree.
TEST(BlockTable, BlocksJsonMayNotRestateMinecraftsFacts) {
  const BlockTable table = BlockTable::fromFile(BlockTable::shippedFile());
  for (const char* entry : {R"({"name": "lava", "opacity": 15})", R"({"name": "torch", "emission": 14})",
                            R"({"name": "oak_log", "properties": {"axis": ["x", "y", "z"]}})",
                            R"({"name": "oak_fence", "collision": {"height": 24}})"}) {
    const std::string json = std::string(R"({"blocks": [{"name": "air", "shape": "none"}, )") + entry + "]}";
    const std::string error = testing::errorOf([&] { BlockRegistry::load(table, json, "test/blocks.json"); });
    EXPECT_NE(error.find("test/blocks.json: blocks[1] ("), std::string::npos) << error;
    EXPECT_NE(error.find("is Minecraft's, given by its block table"), std::string::npos) << error;
  }
  // A block Minecraft does not have is the pack's own, after Minecraft's.
  const BlockRegistry withOwn = BlockRegistry::load(
      table, R"({"blocks": [{"name": "air", "shape": "none"}, {"name": "moon_rock", "emission": 4,
                 "textures": {"all": "stone"}}]})",
      "test/blocks.json");
  EXPECT_EQ(withOwn.id("moon_rock"), 29671);
  EXPECT_FALSE(withOwn[withOwn.id("moon_rock")].minecraft);
  EXPECT_EQ(withOwn.emissions()[withOwn.id("moon_rock")], 4);
  EXPECT_EQ(withOwn.minecraftCollision(withOwn.id("moon_rock")), nullptr);
}

TEST(BlockTable, BadTableNamesTheFileBlockAndKey) {
  const auto errorOf = [](const std::string& blocks) {
    return testing::errorOf([&] {
      BlockTable::fromJson(
          R"({"version": "1", "shapes": [[], [[0, 0, 0, 16, 16, 16]]], "blocks": [)" + blocks + "]}",
          "data/t.json");
    });
  };
  EXPECT_EQ(errorOf(R"({"name": "air", "opacity": 0, "emission": 0, "collision": 2})"),
            "data/t.json: blocks[0] (air).collision: expected a whole number from 0 to 1, got 2");
  EXPECT_EQ(
      errorOf(R"({"name": "lamp", "properties": {"lit": ["true", "false"]}, "opacity": 15,
                       "emission": [15], "collision": 1})"),
      "data/t.json: blocks[0] (lamp).emission: expected a number or one per state (2), got an array of 1");
  EXPECT_EQ(errorOf(R"({"name": "air", "opacity": 16, "emission": 0, "collision": 0})"),
            "data/t.json: blocks[0] (air).opacity: expected a whole number from 0 to 15, got 16");
  const std::string hardness =
      errorOf(R"({"name": "stone", "opacity": 15, "emission": 0, "collision": 1, "hardness": -2})");
  EXPECT_NE(hardness.find("data/t.json: blocks[0] (stone).hardness: "), std::string::npos) << hardness;
}

// How long each block takes to dig, Minecraft's hardness: from the table for Minecraft's blocks, from
// blocks.json (1 unless given) for a pack's own, and never from a pack for Minecraft's.
TEST(BlockTable, HardnessIsMinecraftsOrThePacks) {
  const BlockRegistry& b = defaultBlocks();
  EXPECT_EQ(b[b.id("stone")].hardness, 1.5f);
  EXPECT_EQ(b[b.id("oak_log[axis=x]")].hardness, 2.0f);
  EXPECT_EQ(b[b.id("bedrock")].hardness, kUnbreakable);
  EXPECT_EQ(b[b.id("torch")].hardness, 0.0f);
  EXPECT_EQ(b[b.id("obsidian")].hardness, 50.0f);
  const BlockTable table = BlockTable::fromFile(BlockTable::shippedFile());
  const BlockRegistry own = BlockRegistry::load(
      table, R"({"blocks": [{"name": "air", "shape": "none"}, {"name": "moon_rock", "hardness": 3,
                 "textures": {"all": "stone"}}, {"name": "moon_dust", "textures": {"all": "sand"}}]})",
      "test/blocks.json");
  EXPECT_EQ(own[own.id("moon_rock")].hardness, 3.0f);
  EXPECT_EQ(own[own.id("moon_dust")].hardness, 1.0f);
  const std::string error = testing::errorOf([&] {
    BlockRegistry::load(table,
                        R"({"blocks": [{"name": "stone", "hardness": 9, "textures": {"all": "stone"}}]})",
                        "test/blocks.json");
  });
  EXPECT_NE(error.find("hardness"), std::string::npos) << error;
}

}  // namespace
}  // namespace terrasol
