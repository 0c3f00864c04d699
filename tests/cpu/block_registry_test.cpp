#include <gtest/gtest.h>

#include "core/error.h"
#include "support/error_of.h"
#include "support/world_support.h"
#include "world/chunk_codec.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

TEST(BlockRegistry, ShipsEveryRequiredBlockWithVanillaLightValues) {
  const BlockRegistry& blocks = defaultBlocks();
  for (const char* name :
       {"air",        "stone",      "cobblestone", "dirt",         "grass_block", "sand",     "gravel",
        "bedrock",    "water",      "lava",        "ice",          "snow",        "oak_log",  "oak_leaves",
        "oak_planks", "glass",      "short_grass", "dandelion",    "poppy",       "coal_ore", "iron_ore",
        "gold_ore",   "iron_block", "gold_block",  "copper_block", "glowstone",   "torch"}) {
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
  // Logs are drawn by their models and stop light as cubes do.
  EXPECT_EQ(b("oak_log").shape, BlockShape::Model);
  EXPECT_EQ(b("oak_log").opacity, 15);
  EXPECT_EQ(blocks.stateName(blocks.id("oak_log")), "oak_log[axis=y]");
  EXPECT_EQ(blocks.opacities().size(), blocks.size());
  // Broad enough for a pack to show itself: at least 150 blocks, named as Minecraft names them.
  EXPECT_GE(blocks.blockCount(), 150u);
  for (const char* name :
       {"granite", "polished_andesite", "deepslate", "birch_log", "spruce_door", "acacia_fence_gate",
        "dark_oak_trapdoor", "cut_sandstone", "lime_wool", "black_concrete", "cyan_stained_glass",
        "bookshelf", "deepslate_diamond_ore", "lantern"}) {
    EXPECT_NO_THROW(blocks.id(name)) << name;
  }
}

std::string errorOf(const std::string& json) {
  return testing::errorOf([&] { BlockRegistry::fromJson(json, "test/blocks.json"); });
}

TEST(BlockRegistry, BadDataNamesTheFileBlockAndKey) {
  const std::string air = R"({"name":"air","shape":"none"})";
  auto with = [&](const std::string& block) { return R"({"blocks":[)" + air + "," + block + "]}"; };
  EXPECT_NE(errorOf("{\"blocks\": [\n  {\"name\": \"air\"\n").find("test/blocks.json:3:1: invalid JSON"),
            std::string::npos)
      << errorOf("{\"blocks\": [\n  {\"name\": \"air\"\n");
  EXPECT_NE(errorOf(with(R"({"name":"x","opacity":16,"textures":{"all":"x"}})"))
                .find("blocks[1] (x).opacity: expected a whole number from 0 to 15, got 16"),
            std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","shape":"sphere","textures":{"all":"x"}})"))
                .find("blocks[1] (x).shape: expected one of \"none\", \"cube\", \"cross\", \"liquid\", "
                      "\"torch\", \"model\", got \"sphere\""),
            std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","textures":{"top":"x"}})")).find("leaves a face without a texture"),
            std::string::npos);
  EXPECT_NE(
      errorOf(with(R"({"name":"x","textures":{"al":"x"}})")).find("blocks[1] (x).textures.al: unknown key"),
      std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x"})")).find("blocks[1] (x): needs \"textures\""), std::string::npos);
  EXPECT_NE(
      errorOf(with(R"({"name":"air","shape":"none"})")).find("blocks[1].name: duplicate block name \"air\""),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"blocks":[{"name":"stone","textures":{"all":"stone"}}]})")
                .find("blocks[0]: must be \"air\""),
            std::string::npos);
  EXPECT_NE(errorOf(R"([1,2])").find("test/blocks.json: expected an object, got an array of 2"),
            std::string::npos);
  EXPECT_NE(errorOf(with(R"({"name":"x","emission":"bright","textures":{"all":"x"}})"))
                .find("emission: expected a whole number"),
            std::string::npos);
}

// blocks.json is Terrasol's own: an unknown key is a typo, named with its key path. The gameplay rules
// are read once into enums; an unknown one names the file, the block, the key and the valid rules.
TEST(BlockRegistry, UnknownKeysAndRulesAreNamedWithTheirKeyPath) {
  const std::string air = R"({"name":"air","shape":"none"})";
  auto with = [&](const std::string& block) { return R"({"blocks":[)" + air + "," + block + "]}"; };
  EXPECT_EQ(errorOf(R"({"blocks":[)" + air + R"(],"version":2})"),
            "test/blocks.json: version: unknown key; expected one of \"blocks\"");
  EXPECT_NE(
      errorOf(with(R"({"name":"x","textures":{"all":"x"},"emision":3})"))
          .find("test/blocks.json: blocks[1] (x).emision: unknown key; expected one of \"name\", \"shape\""),
      std::string::npos)
      << errorOf(with(R"({"name":"x","textures":{"all":"x"},"emision":3})"));
  EXPECT_EQ(errorOf(with(R"({"name":"x","textures":{"all":"x"},"collision":{"hieght":24}})")),
            "test/blocks.json: blocks[1] (x).collision.hieght: unknown key; expected one of \"height\", "
            "\"none_when\"");
  EXPECT_EQ(errorOf(with(R"({"name":"x","textures":{"all":"x"},"placement":"stair"})")),
            "test/blocks.json: blocks[1] (x).placement: expected one of \"stairs\", \"slab\", \"axis\", "
            "\"facing\", "
            "\"facing_back\", \"door\", \"trapdoor\", \"wall\", \"torch\", \"layers\", \"pointing\", "
            "\"attached\", \"rotation\", \"two_tall\", \"bed\", \"rail\", got \"stair\"");
  EXPECT_EQ(errorOf(with(R"({"name":"x","textures":{"all":"x"},"connects":"fences"})")),
            "test/blocks.json: blocks[1] (x).connects: expected one of \"fence\", \"pane\", \"wall\", "
            "\"gate\", got "
            "\"fences\"");
  EXPECT_EQ(
      errorOf(with(R"({"name":"x","textures":{"all":"x"},"properties":{"open":["false","true"]},
                            "collision":{"none_when":"open=yes"}})")),
      "test/blocks.json: blocks[1] (x).collision.none_when: expected one of its property=value pairs, got "
      "\"open=yes\"");
  EXPECT_EQ(errorOf(with(R"({"name":"x","textures":{"all":"x"},"wall_variant":"nothing"})")),
            "test/blocks.json: blocks[1] (x).wall_variant: expected the name of a block, got \"nothing\"");
  EXPECT_EQ(errorOf(with(R"({"name":"x","textures":{"all":"x"},"placement":"torch"})")),
            "test/blocks.json: blocks[1] (x): placement \"torch\" needs \"wall_variant\"");
  EXPECT_EQ(
      errorOf(with(R"({"name":"x","layer":"none","textures":{"all":"x"}})")),
      "test/blocks.json: blocks[1] (x).layer: expected one of \"opaque\", \"cutout\", \"translucent\", got "
      "\"none\"");
  // The shipped rules, as read.
  const BlockRegistry& blocks = defaultBlocks();
  auto b = [&](const char* n) -> const BlockType& { return blocks[blocks.id(n)]; };
  EXPECT_EQ(b("torch").placement, PlacementRule::Torch);
  EXPECT_EQ(b("torch").wallVariant, blocks.id("wall_torch"));
  EXPECT_EQ(b("stone").placement, PlacementRule::None);
  EXPECT_EQ(b("stone").wallVariant, kAir);
  EXPECT_EQ(b("oak_fence").connects, Connects::Fence);
  EXPECT_EQ(b("oak_fence_gate").connects, Connects::Gate);
  EXPECT_TRUE(b("oak_fence_gate").opens);
}

// One table per enum: a value's name, a name's value, and the valid names when a name is unknown.
TEST(EnumNames, NameFindAndParseWithTheValidNames) {
  EXPECT_EQ(kConnects.nameOf(Connects::Gate), "gate");
  EXPECT_EQ(kConnects.find("pane"), Connects::Pane);
  EXPECT_FALSE(kConnects.find("fences"));
  EXPECT_FALSE(kConnects.find("")) << "None has no name: the key absent means none";
  EXPECT_EQ(testing::errorOf([] { kConnects.parse("fences", "connects"); }),
            "connects: unknown \"fences\"; expected one of \"fence\", \"pane\", \"wall\", \"gate\"");
}

// Blocks with properties: one state per combination, numbered after the states before them, the last
// property counting fastest, named as Minecraft's commands name them.
const char* kStairsJson = R"({"blocks": [
    {"name": "air", "shape": "none"},
    {"name": "stone", "textures": {"all": "stone"}},
    {"name": "oak_stairs", "textures": {"all": "oak_planks"}, "opacity": 0,
     "properties": {"facing": ["north", "south", "west", "east"], "half": ["top", "bottom"],
                    "waterlogged": ["false", "true"]},
     "default": {"half": "bottom"}},
    {"name": "glass", "layer": "cutout", "opacity": 0, "textures": {"all": "glass"}}]})";

TEST(BlockRegistry, BlocksWithPropertiesHaveAStateForEachCombination) {
  const BlockRegistry blocks = BlockRegistry::fromJson(kStairsJson, "test/blocks.json");
  EXPECT_EQ(blocks.blockCount(), 4u);
  EXPECT_EQ(blocks.size(), 1u + 1u + 16u + 1u);
  const BlockType& stairs = blocks[blocks.id("oak_stairs")];
  EXPECT_EQ(stairs.firstState, 2);
  EXPECT_EQ(stairs.stateCount, 16);
  EXPECT_EQ(blocks.id("glass"), 18) << "the next block's state follows the stairs' sixteen";
  // The default: half=bottom as named, the others their first value.
  EXPECT_EQ(blocks.stateName(blocks.id("oak_stairs")),
            "oak_stairs[facing=north,half=bottom,waterlogged=false]");
  const BlockId eastTop = blocks.id("oak_stairs[half=top,facing=east]");
  EXPECT_EQ(blocks.stateName(eastTop), "oak_stairs[facing=east,half=top,waterlogged=false]");
  EXPECT_EQ(blocks.stateValues(eastTop),
            (StateValues{{"facing", "east"}, {"half", "top"}, {"waterlogged", "false"}}));
  EXPECT_EQ(blocks[eastTop].name, "oak_stairs");
  EXPECT_EQ(blocks.with(eastTop, "half", "bottom"), blocks.id("oak_stairs[facing=east]"));
  EXPECT_FALSE(blocks.with(eastTop, "shape", "straight"));
  EXPECT_FALSE(blocks.with(eastTop, "half", "middle"));
  EXPECT_FALSE(blocks.with(blocks.id("stone"), "half", "top"));
  // Every state's name gives the state back, and its tables are the block's.
  for (BlockId s = 0; s < blocks.size(); ++s) {
    EXPECT_EQ(blocks.id(blocks.stateName(s)), s) << blocks.stateName(s);
    EXPECT_EQ(blocks.opacities()[s], blocks[s].opacity);
  }
  EXPECT_EQ(blocks.stateName(blocks.id("stone")), "stone") << "no properties, no brackets";
}

TEST(BlockRegistry, BadStateNamesSayWhatIsWrong) {
  const BlockRegistry blocks = BlockRegistry::fromJson(kStairsJson, "test/blocks.json");
  const auto error = [&](const std::string& name) { return testing::errorOf([&] { blocks.id(name); }); };
  EXPECT_EQ(error("oak_stair"), "unknown block 'oak_stair'");
  EXPECT_EQ(error("oak_stairs[facing=up]"),
            "'oak_stairs[facing=up]': facing is one of north, south, west, east");
  EXPECT_EQ(error("oak_stairs[shape=straight]"),
            "'oak_stairs[shape=straight]': oak_stairs has no property 'shape'");
  EXPECT_EQ(error("oak_stairs[facing]"), "'oak_stairs[facing]': expected property=value, not 'facing'");
  EXPECT_EQ(error("oak_stairs[facing=east"), "'oak_stairs[facing=east': expected ']' at the end");
  bool found = true;
  EXPECT_EQ(blocks.find("oak_stairs[facing=up]", &found), blocks.id("oak_stairs")) << "the default stands in";
  EXPECT_FALSE(found);
  EXPECT_EQ(blocks.find("nothing", &found), kAir);
  EXPECT_FALSE(found);
}

TEST(BlockRegistry, BadPropertiesNameTheBlockAndKey) {
  const std::string air = R"({"name":"air","shape":"none"})";
  auto with = [&](const std::string& block) { return R"({"blocks":[)" + air + "," + block + "]}"; };
  const auto error = [&](const std::string& block) { return errorOf(with(block)); };
  EXPECT_NE(error(R"({"name":"x","textures":{"all":"x"},"properties":{"axis":[]}})")
                .find("blocks[1] (x).properties.axis: expected a non-empty array of values"),
            std::string::npos);
  EXPECT_NE(error(R"({"name":"x","textures":{"all":"x"},"properties":{"axis":["y","y"]}})")
                .find("properties.axis[1]: lists \"y\" twice"),
            std::string::npos);
  EXPECT_NE(
      error(R"({"name":"x","textures":{"all":"x"},"properties":{"axis":["a=b"]}})").find("may not contain"),
      std::string::npos);
  EXPECT_NE(error(R"({"name":"x","textures":{"all":"x"},"properties":{"axis":["y"]},"default":{"axis":"x"}})")
                .find("blocks[1] (x).default.axis: expected one of the property's values, got \"x\""),
            std::string::npos);
  EXPECT_NE(
      error(R"({"name":"x","textures":{"all":"x"},"properties":{"axis":["y"]},"default":{"facing":"x"}})")
          .find("default.facing: is not one of its properties"),
      std::string::npos);
  EXPECT_NE(error(R"({"name":"x","textures":{"all":"x"},"default":{"axis":"x"}})")
                .find("default: needs \"properties\""),
            std::string::npos);
  EXPECT_NE(error(R"({"name":"x","textures":{"all":"x"},"properties":{"a":["0","1","2","3","4","5","6","7"],
      "b":["0","1","2","3","4","5","6","7"],"c":["0","1","2","3","4","5","6","7"],"d":["0","1","2","3","4","5","6","7"],
      "e":["0","1"]}})")
                .find("more than 4096 states"),
            std::string::npos);
}

// A save keeps states by name: a chunk saved before a block had properties opens with that block in
// its default state, and states round-trip by name even when ids are renumbered.
TEST(BlockRegistry, SavesKeepStatesByNameAcrossRenumbering) {
  const BlockRegistry before = BlockRegistry::fromJson(R"({"blocks": [{"name": "air", "shape": "none"},
      {"name": "oak_stairs", "textures": {"all": "oak_planks"}}, {"name": "glass", "layer": "cutout", "textures": {"all": "glass"}}]})",
                                                       "before.json");
  Chunk old({0, 0});
  old.set(1, 64, 2, before.id("oak_stairs"));
  old.set(2, 64, 2, before.id("glass"));
  const std::vector<std::uint8_t> saved = encodeChunk(old, before);

  const BlockRegistry now = BlockRegistry::fromJson(kStairsJson, "test/blocks.json");
  std::vector<std::string> unknown;
  const auto opened = decodeChunk({0, 0}, saved.data(), saved.size(), now, &unknown);
  EXPECT_EQ(opened->get(1, 64, 2), now.id("oak_stairs"));
  EXPECT_EQ(now.stateName(opened->get(1, 64, 2)), "oak_stairs[facing=north,half=bottom,waterlogged=false]");
  EXPECT_EQ(opened->get(2, 64, 2), now.id("glass")) << "glass moved from id 2 to 18";
  EXPECT_TRUE(unknown.empty());

  Chunk placed({0, 0});
  placed.set(3, 70, 3, now.id("oak_stairs[facing=west,half=top,waterlogged=true]"));
  const std::vector<std::uint8_t> bytes = encodeChunk(placed, now);
  const auto back = decodeChunk({0, 0}, bytes.data(), bytes.size(), now);
  EXPECT_EQ(now.stateName(back->get(3, 70, 3)), "oak_stairs[facing=west,half=top,waterlogged=true]");
  // Opened by a registry where the stairs lost a value: the default stands in, and is reported.
  const auto older = decodeChunk({0, 0}, bytes.data(), bytes.size(), before, &unknown);
  EXPECT_EQ(older->get(3, 70, 3), before.id("oak_stairs"));
  EXPECT_EQ(unknown, std::vector<std::string>{"oak_stairs[facing=west,half=top,waterlogged=true]"});
}

}  // namespace
}  // namespace terrasol

namespace terrasol {
namespace {

// Some states draw other faces: a snowy grass block's sides are snow over dirt; the other faces and
// the other states keep the block's. A bad condition is named with its key path.
TEST(BlockRegistry, StatesMayDrawOtherFaces) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  const auto side = static_cast<std::size_t>(Direction::North), top = static_cast<std::size_t>(Direction::Up);
  EXPECT_EQ(blocks.faceTextures(blocks.id("grass_block[snowy=true]"))[side],
            std::vector<std::string>{"grass_block_snow"});
  EXPECT_EQ(blocks.faceTextures(blocks.id("grass_block[snowy=true]"))[top],
            std::vector<std::string>{"grass_block_top"});
  EXPECT_EQ(blocks.faceTextures(blocks.id("grass_block[snowy=false]"))[side],
            std::vector<std::string>{"grass_block_side"});
  const std::string bad = testing::errorOf([] {
    BlockRegistry::fromJson(R"({"blocks": [{"name": "air", "shape": "none"},
      {"name": "lamp", "properties": {"lit": ["false", "true"]}, "textures": {"all": "lamp"},
       "textures_when": [{"when": "lit=maybe", "textures": {"all": "lamp_on"}}]}]})",
                            "test/blocks.json");
  });
  EXPECT_NE(bad.find("textures_when[0].when"), std::string::npos) << bad;
}

}  // namespace
}  // namespace terrasol
