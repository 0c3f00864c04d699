#include <gtest/gtest.h>

#include "core/error.h"
#include "support/error_of.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

TEST(BlockRegistry, ShipsEveryRequiredBlockWithVanillaLightValues) {
  const BlockRegistry& blocks = defaultBlocks();
  for (const char* name :
       {"air", "stone", "cobblestone", "dirt", "grass_block", "sand", "gravel", "bedrock", "water", "lava", "ice",
        "snow", "oak_log", "oak_leaves", "oak_planks", "glass", "short_grass", "dandelion", "poppy", "coal_ore",
        "iron_ore", "gold_ore", "iron_block", "gold_block", "copper_block", "glowstone", "torch"}) {
    EXPECT_NO_THROW(blocks.id(name)) << name;
  }
  EXPECT_EQ(blocks.id("air"), kAir);
  auto b = [&](const char* n) -> const BlockType& { return blocks[blocks.id(n)]; };
  EXPECT_EQ(b("torch").emission, 14);
  EXPECT_EQ(b("glowstone").emission, 15);
  EXPECT_EQ(b("lava").emission, 15);
  EXPECT_EQ(b("water").opacity, 1);
  EXPECT_EQ(b("ice").opacity, 1);
  EXPECT_EQ(b("oak_leaves").opacity, 1);
  EXPECT_EQ(b("glass").opacity, 0);
  EXPECT_EQ(b("stone").opacity, 15);
  EXPECT_EQ(b("air").opacity, 0);
  EXPECT_EQ(b("short_grass").opacity, 0);
  EXPECT_EQ(b("short_grass").shape, BlockShape::Cross);
  EXPECT_EQ(b("water").layer, RenderLayer::Translucent);
  EXPECT_EQ(b("oak_leaves").layer, RenderLayer::Cutout);
  EXPECT_EQ(b("grass_block").tint, Tint::Grass);
  // Faces in Direction order: west, east, down, up, north, south.
  EXPECT_EQ(b("grass_block").textures[3].front(), "grass_block_top");
  EXPECT_EQ(b("grass_block").textures[2].front(), "dirt");
  EXPECT_EQ(b("grass_block").textures[0].front(), "grass_block_side");
  EXPECT_EQ(b("oak_log").textures[3].front(), "oak_log_top");
  EXPECT_EQ(b("oak_log").textures[5].front(), "oak_log");
  EXPECT_EQ(blocks.opacities().size(), blocks.size());
}

std::string errorOf(const std::string& json) { return testing::errorOf([&] { BlockRegistry::fromJson(json, "test/blocks.json"); }); }

TEST(BlockRegistry, BadDataNamesTheFileBlockAndKey) {
  const std::string air = R"({"name":"air","shape":"none"})";
  auto with = [&](const std::string& block) { return R"({"blocks":[)" + air + "," + block + "]}"; };
  EXPECT_NE(errorOf("{\"blocks\": [\n  {\"name\": \"air\"\n").find("test/blocks.json: invalid JSON"), std::string::npos);
  EXPECT_NE(errorOf("{\"blocks\": [\n  {\"name\": \"air\"\n").find("line 3"), std::string::npos)
      << errorOf("{\"blocks\": [\n  {\"name\": \"air\"\n");
  EXPECT_NE(errorOf(with(R"({"name":"x","opacity":16,"textures":{"all":"x"}})")).find("blocks[1] (x).opacity must be"),
            std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","shape":"sphere","textures":{"all":"x"}})")).find("blocks[1] (x).shape is 'sphere'"),
            std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","textures":{"top":"x"}})")).find("leaves a face without a texture"),
            std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","textures":{"al":"x"}})")).find("unknown face 'al'"), std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x"})")).find("blocks[1] (x) needs \"textures\""), std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"air","shape":"none"})")).find("duplicate block name 'air'"), std::string::npos);
  EXPECT_NE(errorOf(R"({"blocks":[{"name":"stone","textures":{"all":"stone"}}]})").find("blocks[0] must be \"air\""),
            std::string::npos);
  EXPECT_NE(errorOf(R"([1,2])").find("\"blocks\" array"), std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","emission":"bright","textures":{"all":"x"}})")).find("emission must be"),
            std::string::npos);
}

}  // namespace
}  // namespace terrasol
