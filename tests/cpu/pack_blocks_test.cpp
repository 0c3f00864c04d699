// Blocks a resource pack adds (scene/pack_blocks.h): a blockstates file for a name Minecraft's table
// does not know becomes a block with the states its variants and conditions name, drawn by its models.

#include "scene/pack_blocks.h"

#include <gtest/gtest.h>

#include "core/paths.h"
#include "scene/block_atlas.h"
#include "support/pack_builder.h"

namespace terrasol {
namespace {

PackStack stackWith(const testing::PackBuilder& pack) {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  packs.push(ResourcePack::open(pack.dir()));
  return packs;
}

// A lamp of the pack's own (a variants blockstates over a whole cube), a vine-like growth (multipart
// over a thin sheet), a blockstates that cannot be read, and one for a block Minecraft has.
testing::PackBuilder modPack() {
  testing::PackBuilder pack("pack_blocks");
  pack.asset("blockstates/glow_lamp.json", R"({"variants": {
      "lit=false,facing=north": {"model": "block/glow_lamp"}, "lit=true,facing=north": {"model": "block/glow_lamp_on"},
      "lit=false,facing=east": {"model": "block/glow_lamp", "y": 90}, "lit=true,facing=east": {"model": "block/glow_lamp_on", "y": 90}}})")
      .asset("models/block/glow_lamp.json",
             R"({"parent": "block/cube_all", "textures": {"all": "block/glow_lamp"}})")
      .asset("models/block/glow_lamp_on.json",
             R"({"parent": "block/cube_all", "textures": {"all": "block/glow_lamp_on"}})")
      .asset("blockstates/creeper_moss.json", R"({"multipart": [
      {"when": {"north": "true"}, "apply": {"model": "block/creeper_moss"}},
      {"when": {"OR": [{"east": "true"}, {"up": "true|false"}]}, "apply": {"model": "block/creeper_moss", "y": 90}}]})")
      .asset("models/block/creeper_moss.json",
             R"({"textures": {"particle": "#moss", "moss": "block/creeper_moss"},
      "elements": [{"from": [0, 0, 0.5], "to": [16, 16, 0.5], "faces": {"south": {"texture": "#moss"}}}]})")
      .asset("blockstates/broken_thing.json", R"({"variants": )")
      .asset("blockstates/stone.json", R"({"variants": {"": {"model": "block/glow_lamp"}}})")
      .image("glow_lamp.png", testing::solidImage(16, 16, 200, 180, 90))
      .image("glow_lamp_on.png", testing::solidImage(16, 16, 250, 230, 120))
      .image("creeper_moss.png", testing::solidImage(16, 16, 60, 120, 40, 200));
  return pack;
}

TEST(PackBlocks, APacksUnknownBlockstatesBecomeBlocks) {
  const testing::PackBuilder pack = modPack();
  const PackStack packs = stackWith(pack);
  const BlockRegistry base = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  std::vector<PackProblem> problems;
  const BlockRegistry blocks = withPackBlocks(base, packs, problems);
  ASSERT_EQ(blocks.blockCount(), base.blockCount() + 2) << "the lamp and the moss; stone is Minecraft's";
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("broken_thing"), std::string::npos) << problems[0].message;
  EXPECT_EQ(blocks.blocksBeforePacks(), base.blockCount());

  // The lamp: facing and lit as its variants name them, its default the first variant by key, and it
  // fills its cell, so it stops light as stone does.
  const BlockType& lamp = blocks[blocks.id("glow_lamp")];
  ASSERT_EQ(lamp.properties.size(), 2u);
  EXPECT_EQ(lamp.properties[0].name, "facing");
  EXPECT_EQ(lamp.properties[0].values, (std::vector<std::string>{"east", "north"}));
  EXPECT_EQ(lamp.properties[1].name, "lit");
  EXPECT_EQ(lamp.properties[1].values, (std::vector<std::string>{"false", "true"}));
  EXPECT_EQ(lamp.stateCount, 4);
  EXPECT_EQ(blocks.stateName(lamp.defaultState), "glow_lamp[facing=east,lit=false]");
  EXPECT_EQ(blocks.opacities()[blocks.id("glow_lamp[facing=east,lit=true]")], 15);
  // The moss: the properties its conditions name, OR and '|' included; a sheet, so light passes.
  const BlockType& moss = blocks[blocks.id("creeper_moss")];
  ASSERT_EQ(moss.properties.size(), 3u);
  EXPECT_EQ(moss.properties[2].name, "up");
  EXPECT_EQ(moss.properties[2].values, (std::vector<std::string>{"true", "false"}));
  EXPECT_EQ(blocks.opacities()[moss.defaultState], 0);
  EXPECT_EQ(moss.layer, RenderLayer::Cutout);

  // Both draw with their models, neither as the placeholder.
  const BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  const std::vector<BlockDrawing> drawings = blockDrawings(blocks, atlas);
  EXPECT_EQ(drawings[blocks.blockIndex(lamp.defaultState)], BlockDrawing::Model);
  EXPECT_EQ(drawings[blocks.blockIndex(moss.defaultState)], BlockDrawing::Model);
  EXPECT_EQ(atlas.modelQuads[blocks.id("glow_lamp[facing=east,lit=true]")].size(), 6u);
  EXPECT_EQ(atlas.modelQuads[blocks.id("creeper_moss[east=true,north=true,up=false]")].size(), 2u);
  // Without the pack the names stay unknown.
  bool found = true;
  base.find("glow_lamp", &found);
  EXPECT_FALSE(found);
}

}  // namespace
}  // namespace terrasol
