// What the game hears, as plain C++: each block's sound group by Minecraft's families, the events
// edits fire, footsteps and falls by Minecraft's distances, cave mood, and music's timing.

#include <gtest/gtest.h>

#include <map>

#include "ambience.h"
#include "block_sound_cues.h"
#include "footsteps.h"
#include "light/light_engine.h"
#include "music_timer.h"
#include "support/game_world.h"
#include "support/world_support.h"
#include "world/block_sound_rules.h"
#include "world/block_sounds.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;
using testing::flatWorld;

TEST(BlockSounds, FamiliesSoundAsMinecraftAssignsThem) {
  const std::map<std::string, std::string> expected = {
      {"stone", "stone"},
      {"cobblestone", "stone"},
      {"dirt", "gravel"},
      {"coarse_dirt", "gravel"},
      {"clay", "gravel"},
      {"gravel", "gravel"},
      {"grass_block", "grass"},
      {"oak_leaves", "grass"},
      {"short_grass", "grass"},
      {"poppy", "grass"},
      {"oak_planks", "wood"},
      {"spruce_log", "wood"},
      {"oak_door", "wood"},
      {"crafting_table", "wood"},
      {"cherry_planks", "cherry_wood"},
      {"bamboo_planks", "bamboo_wood"},
      {"crimson_planks", "nether_wood"},
      {"crimson_stem", "stem"},
      {"glass", "glass"},
      {"white_stained_glass_pane", "glass"},
      {"ice", "glass"},
      {"glowstone", "glass"},
      {"sea_lantern", "glass"},
      {"white_wool", "wool"},
      {"red_carpet", "wool"},
      {"cactus", "wool"},
      {"sand", "sand"},
      {"red_sand", "sand"},
      {"white_concrete_powder", "sand"},
      {"snow", "snow"},
      {"snow_block", "snow"},
      {"iron_block", "metal"},
      {"gold_block", "metal"},
      {"rail", "metal"},
      {"iron_ore", "stone"},
      {"raw_iron_block", "stone"},
      {"deepslate", "deepslate"},
      {"deepslate_iron_ore", "deepslate"},
      {"deepslate_bricks", "deepslate_bricks"},
      {"enchanting_table", "stone"},
      {"ender_chest", "stone"},
      {"chest", "wood"},
      {"lantern", "lantern"},
      {"jack_o_lantern", "wood"},
      {"mushroom_stem", "wood"},
      {"netherrack", "netherrack"},
      {"nether_bricks", "nether_bricks"},
      {"soul_sand", "soul_sand"},
      {"slime_block", "slime_block"},
      {"honey_block", "honey_block"},
      {"mud", "mud"},
      {"copper_block", "copper"},
      {"waxed_oxidized_cut_copper", "copper"},
      {"anvil", "anvil"},
      {"amethyst_block", "amethyst_block"},
      {"kelp", "wet_grass"},
      {"potted_poppy", "stone"},
      {"water", "empty"},
      {"lava", "empty"},
      {"air", "empty"},
      {"minecraft:oak_planks", "wood"},
  };
  for (const auto& [block, group] : expected) EXPECT_EQ(blockSoundGroup(block).name, group) << block;
}

// Every one of Minecraft's 1 166 blocks gets one of the groups, and each group sounds like a plain
// group every pack can carry.
TEST(BlockSounds, EveryBlockHasAGroupThatFallsBackToAPlainOne) {
  std::map<std::string_view, int> uses;
  for (std::size_t i = 0; i < defaultBlocks().blockCount(); ++i) {
    const SoundGroup& g = blockSoundGroup(defaultBlocks().block(i).name);
    EXPECT_FALSE(g.name.empty());
    ++uses[g.name];
  }
  EXPECT_GE(defaultBlocks().blockCount(), 1166u);
  for (const SoundGroup& g : soundGroups()) {
    bool found = false;
    for (const SoundGroup& h : soundGroups()) found |= h.name == g.like && h.like == h.name;
    EXPECT_TRUE(found) << g.name << " sounds like " << g.like << ", which is not a plain group";
  }
  EXPECT_GT(uses["stone"], 200);
  EXPECT_GT(uses["wood"], 150);
  EXPECT_GT(uses["grass"], 40);
}

TEST(BlockSounds, EveryRuleNamesAGroup) {
  for (const SoundRule& r : blockSoundRules()) {
    bool found = false;
    for (const SoundGroup& g : soundGroups()) found |= g.name == r.group;
    EXPECT_TRUE(found) << "the rule for \"" << r.text << "\" names the unknown group " << r.group;
  }
}

TEST(BlockSounds, OpeningKinds) {
  EXPECT_EQ(openSoundKind("oak_door"), "wooden_door");
  EXPECT_EQ(openSoundKind("iron_door"), "iron_door");
  EXPECT_EQ(openSoundKind("waxed_copper_trapdoor"), "copper_trapdoor");
  EXPECT_EQ(openSoundKind("spruce_trapdoor"), "wooden_trapdoor");
  EXPECT_EQ(openSoundKind("birch_fence_gate"), "fence_gate");
  EXPECT_EQ(openSoundKind("stone"), "");
}

TEST(BlockSoundCues, EditsBreakPlaceAndOpen) {
  const BlockRegistry& blocks = defaultBlocks();
  const BlockSoundTable table(blocks);
  const BlockId stone = blocks.id("stone"), deepslate = blocks.id("deepslate"), water = blocks.id("water");
  const auto broke = table.editCue(stone, kAir, {1, 2, 3}, 40);
  ASSERT_TRUE(broke);
  EXPECT_EQ(broke->sound.event, "block.stone.break");
  EXPECT_EQ(broke->sound.fallback, "");
  EXPECT_EQ(broke->tick, 40);
  EXPECT_EQ(broke->sound.at, glm::vec3(1.5f, 2.5f, 3.5f));
  const auto placed = table.editCue(kAir, deepslate, {0, 0, 0}, 0);
  ASSERT_TRUE(placed);
  EXPECT_EQ(placed->sound.event, "block.deepslate.place");
  EXPECT_EQ(placed->sound.fallback, "block.stone.place");
  EXPECT_FALSE(table.editCue(water, kAir, {0, 0, 0}, 0));  // a bucket's worth of silence
  EXPECT_FALSE(table.editCue(stone, stone, {0, 0, 0}, 0));

  const BlockId shut = *blocks.with(blocks.id("oak_door"), "open", "false");
  const BlockId open = *blocks.with(shut, "open", "true");
  EXPECT_EQ(table.editCue(shut, open, {0, 0, 0}, 0)->sound.event, "block.wooden_door.open");
  EXPECT_EQ(table.editCue(open, shut, {0, 0, 0}, 0)->sound.event, "block.wooden_door.close");
  EXPECT_EQ(table.editCue(shut, kAir, {0, 0, 0}, 0)->sound.event, "block.wood.break");
  // Minecraft's scale: a step is quiet, a break at full volume, both lower than the files for a break.
  const auto step = table.cue(stone, {0, 0, 0}, BlockAction::Step, 0);
  EXPECT_FLOAT_EQ(step->sound.volume, 0.15f);
  EXPECT_FLOAT_EQ(broke->sound.pitch, 0.8f);
}

std::vector<SoundCue> walk(World& world, MoveInput input, int ticks, glm::dvec3 from = {0.5, 64.0, 0.5},
                           bool fly = false) {
  const BlockSoundTable table(world.blocks());
  Player p(from);
  p.flying = fly;
  Footsteps steps;
  std::vector<SoundCue> cues;
  for (int t = 0; t < ticks; ++t) {
    p.tick(world, input);
    steps.tick(p, world, table, t, cues);
  }
  return cues;
}

TEST(Footsteps, AStepEveryBlockAndTwoThirdsWalkedOnTheFloor) {
  World world = flatWorld();
  MoveInput forward;
  forward.forward = 1.0f;
  const std::vector<SoundCue> cues = walk(world, forward, 100);  // 5 s at 4.317 blocks/s: 21.6 blocks
  ASSERT_FALSE(cues.empty());
  for (const SoundCue& c : cues) EXPECT_EQ(c.sound.event, "block.stone.step");
  EXPECT_NEAR(static_cast<double>(cues.size()), 21.6 * Footsteps::kStepScale, 1.5);

  MoveInput sneak = forward;
  sneak.sneak = true;
  EXPECT_TRUE(walk(world, sneak, 100).empty());
  EXPECT_TRUE(walk(world, forward, 100, {0.5, 70.0, 0.5}, true).empty());  // flying
  EXPECT_TRUE(walk(world, {}, 100).empty());                               // standing still

  // A running jump: the distance in the air counts, the step comes on landing.
  MoveInput hop = forward;
  hop.jump = true;
  const std::vector<SoundCue> hops = walk(world, hop, 100);
  EXPECT_GE(static_cast<double>(hops.size()), 0.5 * static_cast<double>(cues.size()));
  for (const SoundCue& c : hops) EXPECT_EQ(c.sound.event, "block.stone.step");
}

TEST(Footsteps, TheFloorUnderfootNamesTheStep) {
  World world = flatWorld();
  const BlockId dirt = defaultBlocks().id("dirt");
  for (int x = -2; x < 30; ++x)
    for (int z = -2; z < 3; ++z) world.setBlock({x, 63, z}, dirt);
  MoveInput forward;
  forward.forward = 1.0f;
  Player facing({0.5, 64.0, 0.5});
  const std::vector<SoundCue> cues = walk(world, forward, 40, {0.5, 64.0, 0.5});
  ASSERT_FALSE(cues.empty());
  EXPECT_EQ(cues.front().sound.event, "block.gravel.step");  // dirt sounds as gravel, as in Minecraft
}

TEST(Footsteps, AFallOfMoreThanThreeBlocksThuds) {
  World world = flatWorld();
  auto falls = [&](double height) {
    int n = 0;
    for (const SoundCue& c : walk(world, {}, 60, {0.5, 64.0 + height, 0.5}))
      n += c.sound.event == "block.stone.fall";
    return n;
  };
  EXPECT_EQ(falls(6.0), 1);
  EXPECT_EQ(falls(2.0), 0);
}

TEST(Ambience, TheCaveMoodFillsInTheDarkAndNotUnderTheSky) {
  World world = flatWorld();
  LightEngine light(world);
  for (int cz = -3; cz <= 3; ++cz)
    for (int cx = -3; cx <= 3; ++cx) light.chunkLoaded({cx, cz});
  const BlockSoundTable table(world.blocks());
  auto caves = [&](glm::dvec3 eye, int ticks) {
    Ambience ambience;
    std::mt19937 random(1);
    std::vector<SoundCue> cues;
    int n = 0;
    for (int t = 0; t < ticks; ++t) ambience.tick(world, light, table, eye, t, random, cues);
    for (const SoundCue& c : cues) n += c.sound.event == kCaveEvent;
    return n;
  };
  // Deep in the stone every cell is dark: the mood fills in Minecraft's 6 000 ticks, then empties.
  EXPECT_EQ(caves({0.5, 30.5, 0.5}, Ambience::kMoodTicks - 10), 0);
  EXPECT_EQ(caves({0.5, 30.5, 0.5}, Ambience::kMoodTicks + 10), 1);
  EXPECT_EQ(caves({0.5, 80.5, 0.5}, 3 * Ambience::kMoodTicks), 0);  // under the open sky
}

TEST(Ambience, WindRisesWithHeightUnderOpenSky) {
  World world = flatWorld();
  LightEngine light(world);
  for (int cz = -3; cz <= 3; ++cz)
    for (int cx = -3; cx <= 3; ++cx) light.chunkLoaded({cx, cz});
  const BlockSoundTable table(world.blocks());
  auto windAt = [&](double y) {
    Ambience ambience;
    std::mt19937 random(1);
    std::vector<SoundCue> cues;
    for (int t = 0; t < 200; ++t) ambience.tick(world, light, table, {0.5, y, 0.5}, t, random, cues);
    return ambience.wind();
  };
  EXPECT_EQ(windAt(70.0), 0.0f);
  EXPECT_GT(windAt(130.0), 0.4f);
  EXPECT_GT(windAt(200.0), 0.95f);
  EXPECT_EQ(windAt(30.0), 0.0f);  // inside the stone: no sky
}

TEST(Ambience, EnteringAndLeavingWater) {
  World world = flatWorld();
  const BlockId water = defaultBlocks().id("water");
  for (int y = 64; y < 68; ++y)
    for (int x = -3; x <= 3; ++x)
      for (int z = -3; z <= 3; ++z) world.setBlock({x, y, z}, water);
  LightEngine light(world);
  for (int cz = -3; cz <= 3; ++cz)
    for (int cx = -3; cx <= 3; ++cx) light.chunkLoaded({cx, cz});
  const BlockSoundTable table(world.blocks());
  Ambience ambience;
  std::mt19937 random(1);
  std::vector<SoundCue> cues;
  const double eyes[] = {70.0, 66.0, 66.0, 69.0};  // above, under, under, above
  for (int t = 0; t < 4; ++t) ambience.tick(world, light, table, {0.5, eyes[t], 0.5}, t, random, cues);
  std::vector<std::string> heard;
  for (const SoundCue& c : cues) heard.push_back(c.sound.event);
  EXPECT_EQ(heard, (std::vector<std::string>{std::string(kEnterWaterEvent), std::string(kLeaveWaterEvent)}));
  EXPECT_EQ(cues[0].tick, 1);
  EXPECT_EQ(cues[1].tick, 3);
  EXPECT_FALSE(ambience.underwater());
}

// Minecraft's animate ticks: 667 random cells within 16 blocks a tick; flowing water murmurs 1 in 64,
// still water never; lava under air pops 1 in 100 and murmurs 1 in 200.
TEST(Ambience, FlowingWaterAndLavaAreHeardAtMinecraftsOdds) {
  const BlockRegistry& blocks = defaultBlocks();
  auto heard = [&](BlockId fluid) {
    World world = flatWorld();
    for (int y = 64; y < 67; ++y)
      for (int x = -7; x <= 7; ++x)
        for (int z = -7; z <= 7; ++z) world.setBlock({x, y, z}, fluid);
    LightEngine light(world);
    const BlockSoundTable table(world.blocks());
    Ambience ambience;
    std::mt19937 random(5);
    std::vector<SoundCue> cues;
    for (int t = 0; t < 400; ++t) ambience.tick(world, light, table, {0.5, 70.5, 0.5}, t, random, cues);
    std::map<std::string, int> n;
    for (const SoundCue& c : cues) ++n[c.sound.event];
    return n;
  };
  // 675 fluid cells of the 29 791 sampled from: 667 x 675 / 29 791 = 15.1 a tick.
  const double sampled = 400.0 * 667.0 * 675.0 / 29791.0;
  const BlockId flowing = *blocks.with(blocks.id("water"), "level", "1");
  const auto water = heard(flowing);
  EXPECT_NEAR(water.at(std::string(kWaterEvent)), sampled / 64.0, 0.3 * sampled / 64.0);
  EXPECT_TRUE(heard(blocks.id("water")).empty());  // still water
  // Lava: only the top layer has air above it, a third of the cells.
  const auto lava = heard(blocks.id("lava"));
  EXPECT_NEAR(lava.at(std::string(kLavaPopEvent)), sampled / 3.0 / 100.0, 0.4 * sampled / 3.0 / 100.0);
  EXPECT_NEAR(lava.at(std::string(kLavaEvent)), sampled / 3.0 / 200.0, 0.5 * sampled / 3.0 / 200.0);
}

TEST(MusicTimer, MinecraftsDelaysAndNightsTrack) {
  MusicTimer timer;
  std::mt19937 random(7);
  int started = -1;
  for (int t = 0; t < 200 && started < 0; ++t)
    if (timer.tick(false, false, random)) started = t;
  EXPECT_EQ(started, MusicTimer::kFirstDelay - 1);
  for (int t = 0; t < 1000; ++t) EXPECT_FALSE(timer.tick(true, false, random));  // the track plays
  int quiet = 0;
  std::optional<std::string_view> next;
  while (!(next = timer.tick(false, true, random))) ++quiet;
  EXPECT_GE(quiet + 1, MusicTimer::kMinDelay);
  EXPECT_LE(quiet + 1, MusicTimer::kMaxDelay);
  EXPECT_EQ(*next, MusicTimer::kNight);
  EXPECT_FALSE(MusicTimer::night(6000));
  EXPECT_FALSE(MusicTimer::night(12999));
  EXPECT_TRUE(MusicTimer::night(13000));
  EXPECT_TRUE(MusicTimer::night(18000 + 24000 * 3));
  EXPECT_TRUE(MusicTimer::night(-6000));  // a day before noon is midnight
  EXPECT_FALSE(MusicTimer::night(23000));
}

}  // namespace
}  // namespace terrasol
