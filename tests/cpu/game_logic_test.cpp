// The game's plain-C++ parts: player physics against Minecraft's numbers, controls, input scripts
// and settings files (block picking and placement: placement_test.cpp).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <thread>

#include "controls.h"
#include "core/day_cycle.h"
#include "core/error.h"
#include "frame_rate.h"
#include "hotbar.h"
#include "input_script.h"
#include "player.h"
#include "settings.h"
#include "shader_pack_list.h"
#include "support/error_of.h"
#include "support/game_world.h"
#include "support/world_support.h"
#include "time_controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace terrasol {
namespace {

using testing::defaultBlocks;
using testing::defaultShapes;
using testing::flatWorld;
using testing::scratchDir;

using testing::errorOf;

void runTicks(Player& p, const World& w, const MoveInput& in, int ticks) {
  for (int i = 0; i < ticks; ++i) p.tick(w, in);
}

TEST(PlayerTest, StandsOnTheFloorAndJumpsMinecraftsHeight) {
  const World world = flatWorld();
  Player p({0.5, 70.0, 0.5});
  runTicks(p, world, {}, 60);
  EXPECT_TRUE(p.onGround());
  EXPECT_NEAR(p.position().y, 64.0, 1e-6);
  MoveInput jump;
  jump.jump = true;
  p.tick(world, jump);
  double top = 0.0;
  for (int i = 0; i < 30; ++i) {
    p.tick(world, {});
    top = std::max(top, p.position().y - 64.0);
  }
  EXPECT_NEAR(top, 1.2522, 0.01);  // Minecraft's jump apex
  EXPECT_TRUE(p.onGround());
}

TEST(PlayerTest, WalksSprintsSneaksAndFliesAtMinecraftsSpeeds) {
  const World world = flatWorld(7);
  const auto speed = [&](MoveInput in, bool fly) {
    Player p({0.5, fly ? 80.0 : 64.0, 0.5});
    p.flying = fly;
    runTicks(p, world, {}, 5);
    runTicks(p, world, in, 100);  // reach steady speed
    const double z0 = p.position().z;
    runTicks(p, world, in, 20);
    return (p.position().z - z0);  // blocks in one second (yaw 0 looks +z)
  };
  MoveInput walk;
  walk.forward = 1.0f;
  EXPECT_NEAR(speed(walk, false), 4.317, 0.02);
  MoveInput sprint = walk;
  sprint.sprint = true;
  EXPECT_NEAR(speed(sprint, false), 5.612, 0.02);
  MoveInput sneak = walk;
  sneak.sneak = true;
  EXPECT_NEAR(speed(sneak, false), 1.295, 0.02);
  EXPECT_NEAR(speed(walk, true), 10.89, 0.05);
  EXPECT_NEAR(speed(sprint, true), 21.78, 0.1);
}

TEST(PlayerTest, FallsAtTerminalSpeedWithoutTunnelling) {
  const World world = flatWorld();
  Player p({0.5, 300.0, 0.5});
  double fastest = 0.0;
  for (int i = 0; i < 400 && !p.onGround(); ++i) {
    p.tick(world, {});
    fastest = std::max(fastest, -p.velocity().y);
    ASSERT_GE(p.position().y, 64.0 - 1e-9) << "fell into the floor at tick " << i;
  }
  EXPECT_TRUE(p.onGround());
  EXPECT_NEAR(p.position().y, 64.0, 1e-6);
  // Minecraft's fall: v(n) = 3.92 (1 - 0.98^n) blocks a tick, never above 78.4 blocks/s; 236 blocks
  // take 101 ticks, reaching 68 blocks/s.
  EXPECT_GT(fastest, 66.0);
  EXPECT_LT(fastest, 78.4);
}

TEST(PlayerTest, NoSpeedGoesThroughAOneBlockWall) {
  World world = flatWorld();
  for (int y = 64; y < 70; ++y)
    for (int x = -8; x < 8; ++x) world.setBlock({x, y, 5}, defaultBlocks().id("glass"));
  for (const double speed : {200.0, 600.0, 1e6}) {  // 10 blocks a tick and more: the wall is 4.2 away
    Player p({0.5, 64.0, 0.5});
    p.push({0.0, 0.0, speed});
    p.tick(world, {});
    EXPECT_NEAR(p.box().max.z, 5.0, 1e-6) << speed << " blocks/s";
  }
}

TEST(PlayerTest, AThinWallStopsAnyHorizontalSpeed) {
  World world = flatWorld();
  for (int y = 64; y < 70; ++y)
    for (int x = -8; x < 8; ++x) world.setBlock({x, y, 5}, defaultBlocks().id("glass"));
  Player p({0.5, 64.0, 0.5});
  p.flying = true;
  MoveInput fast;
  fast.forward = 1.0f;
  fast.sprint = true;
  runTicks(p, world, fast, 100);
  EXPECT_NEAR(p.box().max.z, 5.0, 1e-6);  // touching the wall, not through it
}

TEST(PlayerTest, WallsOneBlockHighAreNotSteppedOnto) {
  World world = flatWorld();
  for (int x = -8; x < 8; ++x) world.setBlock({x, 64, 3}, defaultBlocks().id("stone"));
  Player p({0.5, 64.0, 0.5});
  MoveInput walk;
  walk.forward = 1.0f;
  runTicks(p, world, walk, 40);
  EXPECT_NEAR(p.position().y, 64.0, 1e-6);
  EXPECT_NEAR(p.box().max.z, 3.0, 1e-6);
  MoveInput walkJump = walk;
  walkJump.jump = true;
  runTicks(p, world, walkJump, 8);
  runTicks(p, world, {}, 20);
  EXPECT_NEAR(p.position().y, 65.0, 1e-6) << "jumping gets on top";
}

TEST(PlayerTest, StepsOntoSlabsAndUpStairsWithoutJumping) {
  World world = flatWorld();
  world.setShapes(&defaultShapes());
  MoveInput walk;
  walk.forward = 1.0f;  // towards +z
  for (int z = 3; z < 12; ++z)
    for (int x = -8; x < 8; ++x) world.setBlock({x, 64, z}, defaultBlocks().id("stone_slab"));
  Player p({0.5, 64.0, 0.5});
  runTicks(p, world, walk, 30);
  EXPECT_NEAR(p.position().y, 64.5, 1e-6) << "on the slabs";
  EXPECT_GT(p.position().z, 4.0);
  // A staircase climbing south, four steps up, each stair on the one below's level.
  World stairs = flatWorld();
  stairs.setShapes(&defaultShapes());
  for (int step = 0; step < 4; ++step) {
    for (int x = -8; x < 8; ++x) {
      for (int y = 64; y < 64 + step; ++y) stairs.setBlock({x, y, 3 + step}, defaultBlocks().id("stone"));
      stairs.setBlock({x, 64 + step, 3 + step}, defaultBlocks().id("oak_stairs[facing=south]"));
    }
  }
  for (int z = 7; z < 14; ++z)  // the landing
    for (int x = -8; x < 8; ++x)
      for (int y = 64; y < 68; ++y) stairs.setBlock({x, y, z}, defaultBlocks().id("stone"));
  Player climber({0.5, 64.0, 0.5});
  runTicks(climber, stairs, walk, 45);
  EXPECT_NEAR(climber.position().y, 68.0, 1e-6) << "up four stairs to the landing";
  EXPECT_GT(climber.position().z, 7.0);
  EXPECT_LT(climber.position().z, 13.0);
  // A full block is not a step (0.6 at most), with shapes or without.
  World wall = flatWorld();
  wall.setShapes(&defaultShapes());
  for (int x = -8; x < 8; ++x) wall.setBlock({x, 64, 3}, defaultBlocks().id("stone_slab[type=double]"));
  Player blocked({0.5, 64.0, 0.5});
  runTicks(blocked, wall, walk, 30);
  EXPECT_NEAR(blocked.position().y, 64.0, 1e-6);
  EXPECT_NEAR(blocked.box().max.z, 3.0, 1e-6);
}

// Fences and walls are 1.5 blocks high to a player: jumping (1.25) does not clear them, as it clears
// a block. A closed gate is a fence; an open one lets the player through.
TEST(PlayerTest, FencesStopAJumpAndOpenGatesLetThrough) {
  const auto reach = [](const char* block, bool jump) {
    World world = flatWorld();
    world.setShapes(&defaultShapes());
    for (int x = -8; x < 8; ++x) world.setBlock({x, 64, 3}, defaultBlocks().id(block));
    for (int z = 4; z < 8; ++z)
      for (int x = -8; x < 8; ++x) world.setBlock({x, 64, z}, defaultBlocks().id("stone"));
    MoveInput walk;
    walk.forward = 1.0f;
    walk.jump = jump;
    Player p({0.5, 64.0, 0.5});
    runTicks(p, world, walk, 60);
    return p.position().z;
  };
  EXPECT_GT(reach("stone", true), 4.0) << "a block is jumped onto";
  EXPECT_LT(reach("oak_fence", true), 3.5)
      << "a fence is not (its post, 6..10 / 16 into the cell, stops the player)";
  EXPECT_LT(reach("cobblestone_wall", true), 3.5);
  EXPECT_LT(reach("oak_fence_gate[facing=south]", true), 3.5);
  EXPECT_GT(reach("oak_fence_gate[facing=south,open=true]", false), 3.5) << "walked through an open gate";
}

TEST(PlayerTest, ATopSlabIsAHeadHighBeamAndABottomSlabAFloor) {
  World world = flatWorld();
  world.setShapes(&defaultShapes());
  // A top slab at head height (y 65.5..66): the player (1.8 high) cannot pass under it...
  for (int x = -8; x < 8; ++x) world.setBlock({x, 65, 3}, defaultBlocks().id("stone_slab[type=top]"));
  MoveInput walk;
  walk.forward = 1.0f;
  Player p({0.5, 64.0, 0.5});
  runTicks(p, world, walk, 30);
  EXPECT_NEAR(p.box().max.z, 3.0, 1e-6);
  // ...but a bottom slab there leaves room above the stone floor for nothing either, while one a
  // block higher (y 66..66.5) lets the player walk under it.
  World high = flatWorld();
  high.setShapes(&defaultShapes());
  for (int x = -8; x < 8; ++x) high.setBlock({x, 66, 3}, defaultBlocks().id("stone_slab"));
  Player under({0.5, 64.0, 0.5});
  runTicks(under, high, walk, 30);
  EXPECT_GT(under.position().z, 4.0) << "1.8 tall under a slab 2 blocks up";
  // Sneaking stops at a slab's edge as at a block's.
  World ledge = flatWorld();
  ledge.setShapes(&defaultShapes());
  for (int z = -8; z < 8; ++z)
    for (int x = -8; x < 8; ++x) {
      ledge.setBlock({x, 63, z}, z < 3 ? defaultBlocks().id("stone_slab[type=top]") : kAir);
    }
  for (int z = 3; z < 8; ++z)
    for (int x = -8; x < 8; ++x) ledge.setBlock({x, 62, z}, kAir);
  Player sneaker({0.5, 64.0, 0.5});
  MoveInput sneak = walk;
  sneak.sneak = true;
  runTicks(sneaker, ledge, sneak, 60);
  EXPECT_NEAR(sneaker.position().y, 64.0, 1e-6) << "still on the slab";
  EXPECT_LT(sneaker.box().min.z, 3.0);
}

TEST(PlayerTest, SneakingStopsAtTheEdge) {
  World world = flatWorld();
  for (int y = 60; y < 64; ++y)
    for (int x = -8; x < 8; ++x) world.setBlock({x, y, 3}, kAir);  // a trench at z = 3
  Player p({0.5, 64.0, 0.5});
  MoveInput sneak;
  sneak.forward = 1.0f;
  sneak.sneak = true;
  runTicks(p, world, {}, 5);
  runTicks(p, world, sneak, 100);
  EXPECT_NEAR(p.position().y, 64.0, 1e-6);
  EXPECT_LE(p.box().min.z, 3.0) << "still over the edge's block";
  MoveInput walk;
  walk.forward = 1.0f;
  runTicks(p, world, walk, 40);
  EXPECT_LT(p.position().y, 64.0) << "walking falls in";
}

TEST(PlayerTest, WaterSlowsWalking) {
  World world = flatWorld();
  for (int y = 64; y < 66; ++y)
    for (int z = -8; z < 40; ++z)
      for (int x = -8; x < 8; ++x) world.setBlock({x, y, z}, defaultBlocks().id("water"));
  Player p({0.5, 64.0, 0.5});
  MoveInput walk;
  walk.forward = 1.0f;
  runTicks(p, world, walk, 20);
  const double z0 = p.position().z;
  runTicks(p, world, walk, 20);
  EXPECT_TRUE(p.inWater());
  EXPECT_LT(p.position().z - z0, 4.317 * 0.5);
  EXPECT_GT(p.position().z - z0, 0.5);
}

TEST(PlayerTest, FlyingEndsOnLandingAndUnloadedGroundHoldsStill) {
  const World world = flatWorld(1);
  Player p({0.5, 66.0, 0.5});
  p.flying = true;
  MoveInput down;
  down.sneak = true;
  runTicks(p, world, down, 40);
  EXPECT_FALSE(p.flying);
  EXPECT_NEAR(p.position().y, 64.0, 1e-6);
  Player far({1000.5, 100.0, 1000.5});
  runTicks(far, world, {}, 20);
  EXPECT_EQ(far.position(), glm::dvec3(1000.5, 100.0, 1000.5));
}

TEST(PlayerTest, SlowFramesRunAtMostTenTicks) {
  double acc = 0.0;
  EXPECT_EQ(Player::ticksFor(acc, 0.049), 0);
  EXPECT_EQ(Player::ticksFor(acc, 0.002), 1);
  EXPECT_EQ(Player::ticksFor(acc, 5.0), 10);
  EXPECT_EQ(acc, 0.0);
  EXPECT_EQ(Player::ticksFor(acc, -1.0), 0);
}

TEST(PlayerTest, LookClampsPitchAndFacesMinecraftsWay) {
  Player p;
  p.look(0.0f, 500.0f);
  EXPECT_EQ(p.pitch, 90.0f);
  EXPECT_NEAR(p.forward().y, -1.0, 1e-9);
  p.pitch = 0.0f;
  p.yaw = 90.0f;
  EXPECT_NEAR(p.forward().x, -1.0, 1e-9);  // yaw 90 faces west
}

TEST(FrameRateTest, MedianOnePercentLowAndMean) {
  std::vector<double> frames(198, 0.010);  // 10 ms frames
  frames.push_back(0.100);                 // and the two slowest: the 1 % of 200
  frames.push_back(0.050);
  const FrameRateSummary s = summarizeFrames(frames);
  EXPECT_EQ(s.frames, 200u);
  EXPECT_NEAR(s.medianFps, 100.0, 1e-9);
  EXPECT_NEAR(s.onePercentLowMs, 75.0, 1e-9);  // the mean of 100 and 50 ms
  EXPECT_NEAR(s.onePercentLowFps, 1.0 / 0.075, 1e-9);
  EXPECT_NEAR(s.seconds, 198 * 0.010 + 0.150, 1e-9);
  EXPECT_NEAR(s.meanFps, 200.0 / s.seconds, 1e-9);
  const FrameRateSummary one = summarizeFrames({0.020});
  EXPECT_NEAR(one.onePercentLowFps, 50.0, 1e-9) << "fewer than 100 frames: the slowest one";
  EXPECT_EQ(summarizeFrames({}).frames, 0u);
}

TEST(ControlsTest, PressesCountOnceAndHoldsCarryOver) {
  KeyBindings keys;
  Controls c(keys);
  c.key(GLFW_KEY_W, true);
  c.key(GLFW_KEY_W, true);  // key repeat
  FrameInput a = c.take();
  EXPECT_TRUE(a.isHeld(Action::Forward));
  EXPECT_TRUE(a.wasPressed(Action::Forward));
  FrameInput b = c.take();
  EXPECT_TRUE(b.isHeld(Action::Forward));
  EXPECT_FALSE(b.wasPressed(Action::Forward));
  keys.bind(Action::Jump, GLFW_KEY_W);  // rebound: one key, two actions
  c.key(GLFW_KEY_W, false);
  c.key(GLFW_KEY_W, true);
  FrameInput d = c.take();
  EXPECT_TRUE(d.wasPressed(Action::Jump));
  EXPECT_TRUE(d.wasPressed(Action::Forward));
  c.key(kEscapeKey, true);
  EXPECT_TRUE(c.take().menuPressed);
}

TEST(ControlsTest, ADoubleTapIsTwoPressesWithinItsTime) {
  DoubleTap tap;
  EXPECT_FALSE(tap.press(1.0));
  EXPECT_TRUE(tap.press(1.25));
  EXPECT_FALSE(tap.press(1.3)) << "the second press of a pair starts no new one";
  EXPECT_FALSE(tap.press(2.0));
  EXPECT_FALSE(tap.press(2.35)) << "too slow: a new first press";
  EXPECT_TRUE(tap.press(2.5));
}

TEST(HotbarTest, WheelWrapsAndPickSelectsOrReplaces) {
  const BlockRegistry& blocks = defaultBlocks();
  Hotbar bar(blocks);
  EXPECT_EQ(blocks.stateName(bar.held()), "stone");
  bar.scroll(-1.0);  // wheel down: the next slot
  EXPECT_EQ(bar.selected(), 1);
  bar.scroll(3.0);
  EXPECT_EQ(bar.selected(), Hotbar::kSlots - 2);
  bar.scroll(-2.0);
  EXPECT_EQ(bar.selected(), 0) << "round past the last slot";
  bar.pick(bar.at(7));  // already in the bar: selected
  EXPECT_EQ(bar.selected(), 7);
  const BlockId glass = blocks.id("glass");
  bar.pick(glass);  // not in the bar: into the selected slot
  EXPECT_EQ(bar.selected(), 7);
  EXPECT_EQ(bar.held(), glass);
}

TEST(TimeControlsTest, SpeedsStopAndPresets) {
  TimeControls time;
  std::int64_t t = 100;
  time.tick(t);
  EXPECT_EQ(t, 101);
  time.faster();
  time.tick(t);
  EXPECT_EQ(t, 111);
  time.faster();
  time.faster();  // round to x1
  EXPECT_EQ(time.speed(), 1);
  time.toggleStop();
  time.tick(t);
  EXPECT_EQ(t, 111);
  EXPECT_EQ(TimeControls::nextPreset(0), 1000);
  EXPECT_EQ(TimeControls::nextPreset(6000), 12000);
  EXPECT_EQ(TimeControls::nextPreset(18000), kTicksPerDay + 1000) << "midnight: the next morning";
  EXPECT_EQ(TimeControls::nextPreset(3 * kTicksPerDay + 7000), 3 * kTicksPerDay + 12000);
}

TEST(ControlsTest, KeyNamesRoundTrip) {
  for (int key : {GLFW_KEY_W, GLFW_KEY_1, GLFW_KEY_F3, GLFW_KEY_F12, GLFW_KEY_SPACE, GLFW_KEY_LEFT_SHIFT}) {
    EXPECT_EQ(keyNamed(keyName(key)), key) << keyName(key);
  }
  EXPECT_FALSE(keyNamed("HYPER"));
  EXPECT_FALSE(keyNamed("F99"));
  for (std::size_t i = 0; i < kActionCount; ++i) {
    EXPECT_EQ(actionNamed(actionName(static_cast<Action>(i))), static_cast<Action>(i));
  }
}

TEST(InputScriptTest, ParsesSortsAndPlaysInTimeOrder) {
  const InputScript script = parseInputScript(R"({ "step": 0.05, "events": [
      { "t": 1.0, "key": "W", "down": false },
      { "t": 0.0, "key": "W", "down": true },
      { "t": 0.5, "button": "left" },
      { "t": 0.5, "look": [90, 45] },
      { "t": 2.0, "command": "quit" } ] })",
                                              "s.json");
  ASSERT_EQ(script.events.size(), 5u);
  EXPECT_NEAR(script.step, 0.05, 1e-6);
  ScriptPlayer player(script);
  EXPECT_EQ(player.due(0.0).size(), 1u);
  const auto half = player.due(0.5);
  ASSERT_EQ(half.size(), 2u);
  EXPECT_EQ(half[0].kind, ScriptEvent::Kind::Button);  // file order among equal times
  EXPECT_FALSE(half[0].down);
  EXPECT_EQ(half[1].value, glm::dvec2(90, 45));
  EXPECT_EQ(player.due(1.9).size(), 1u);
  EXPECT_FALSE(player.finished());
  EXPECT_EQ(player.due(2.0)[0].command, ScriptCommand::Quit);
  EXPECT_TRUE(player.finished());
}

TEST(InputScriptTest, BadScriptsNameTheFileAndTheEvent) {
  const auto error = [](const std::string& text) {
    return errorOf([&] { parseInputScript(text, "script.json"); });
  };
  EXPECT_NE(
      error(R"({"events": [{"t": 0, "key": "HYPER"}]})").find("script.json: events[0].key: unknown key"),
      std::string::npos);
  EXPECT_NE(error(R"({"events": [{"key": "W"}]})").find("events[0]: missing \"t\""), std::string::npos);
  EXPECT_NE(error(R"({"events": [{"t": 0, "key": "W", "button": "left"}]})").find("exactly one of"),
            std::string::npos);
  EXPECT_NE(error(R"({"events": [{"t": 0, "look": [0, 91]}]})").find("events[0].look[1]"), std::string::npos);
  EXPECT_NE(error(R"({"events": [{"t": 0, "command": "dance"}]})").find("events[0].command"),
            std::string::npos);
  EXPECT_NE(error(R"({"events": [{"t": 0, "scroll": 1, "down": true}]})").find("events[0].down"),
            std::string::npos);
  EXPECT_NE(error(R"({"events": [)").find("script.json:1:"), std::string::npos);
  EXPECT_NE(error(R"({"step": 0})").find("step"), std::string::npos);
  EXPECT_NE(error(R"({"events": [{"t": 0, "command": "place_prop"}]})")
                .find("events[0]: \"place_prop\" needs \"model\""),
            std::string::npos);
  EXPECT_NE(error(R"({"events": [{"t": 0, "command": "save", "model": "a.glb"}]})").find("events[0].model"),
            std::string::npos);
  EXPECT_EQ(parseInputScript(R"({"events": [{"t": 0, "command": "place_prop", "model": "a.glb"}]})", "s.json")
                .events[0]
                .model,
            "a.glb");
}

TEST(SettingsTest, SaveAndLoadRoundTripAndMissingMeansDefaults) {
  const auto dir = scratchDir("settings");
  const auto file = dir / "sub" / "settings.json";
  std::filesystem::remove_all(dir / "sub");
  const GameSettings defaults = loadSettings(file);
  EXPECT_EQ(defaults.viewDistance, 6);
  GameSettings s;
  s.viewDistance = 12;
  s.fov = 90.0f;
  s.shadow.mode = ShadowMode::Cascaded;
  s.reflections.enabled = true;
  s.reflections.resolutionScale = 0.5f;
  s.shadow.pcfSamples = 3;
  s.packs = {{dir / "packs" / "a", true}, {dir / "packs" / "b", false}};
  s.shaderpack = dir / "shaderpacks" / "a.zip";
  s.antialiasing = Antialiasing::Taa;
  s.bloom = {true, 0.08f};
  s.clouds = {CloudMode::Flat, false};
  s.fog = {0.01f, 70.0f, 12.0f};
  s.shafts = {true, 12, 0.5f};
  s.keys.bind(Action::Jump, GLFW_KEY_J);
  s.sound.music = 0.25f;
  s.sound.blocks = 0.0f;
  s.survivalDigging = true;
  saveSettings(file, s);
  const GameSettings back = loadSettings(file);
  EXPECT_EQ(back.viewDistance, 12);
  EXPECT_EQ(back.fov, 90.0f);
  EXPECT_EQ(back.shadow, s.shadow) << "every shadow setting comes back";
  EXPECT_EQ(back.reflections, s.reflections);
  EXPECT_EQ(back.shadow.pcfSamples, 3);
  EXPECT_EQ(back.packs, s.packs);
  EXPECT_EQ(back.shaderpack, s.shaderpack);
  EXPECT_EQ(back.antialiasing, Antialiasing::Taa);
  EXPECT_EQ(back.bloom, s.bloom);
  EXPECT_EQ(back.clouds, s.clouds);
  EXPECT_EQ(back.fog, s.fog);
  EXPECT_EQ(back.shafts, s.shafts);
  EXPECT_EQ(defaults.clouds.mode, CloudMode::Fancy) << "the game has clouds unless told otherwise";
  EXPECT_TRUE(defaults.shaderpack.empty()) << "Terrasol's own pipeline";
  EXPECT_EQ(back.keys.key(Action::Jump), GLFW_KEY_J);
  EXPECT_EQ(back.keys.key(Action::Forward), GLFW_KEY_W);
  EXPECT_EQ(back.sound.music, 0.25f);
  EXPECT_EQ(back.sound.blocks, 0.0f);
  EXPECT_EQ(back.sound.master, 1.0f);
  EXPECT_EQ(defaults.sound.music, 1.0f);
  EXPECT_TRUE(back.survivalDigging);
  EXPECT_FALSE(defaults.survivalDigging) << "blocks break at a click unless asked";
}

TEST(SettingsTest, MalformedSettingsNameTheKey) {
  const auto error = [](const std::string& text) {
    return errorOf([&] { parseSettings(text, "settings.json"); });
  };
  EXPECT_NE(error(R"({"view_distance": 99})").find("settings.json: view_distance"), std::string::npos);
  EXPECT_NE(error(R"({"shadow": {"mode": "fancy"}})").find("shadow.mode"), std::string::npos);
  EXPECT_NE(error(R"({"keys": {"jump": "HYPER"}})").find("keys.jump: unknown key"), std::string::npos);
  EXPECT_NE(error(R"({"keys": {"fly": "F"}})").find("keys.fly: unknown action"), std::string::npos);
  EXPECT_NE(error(R"({"keys": {"jump": "ESCAPE"}})").find("keys.jump"), std::string::npos);
  EXPECT_NE(error(R"({"packs": [{"enabled": true}]})").find("packs[0]"), std::string::npos);
  EXPECT_NE(error(R"({"fov": )").find("settings.json:1:"), std::string::npos);
  EXPECT_NE(error(R"({"shaderpack": 3})").find("shaderpack"), std::string::npos);
  EXPECT_NE(error(R"({"sound": {"music": 1.5}})").find("sound.music"), std::string::npos);
  EXPECT_NE(error(R"({"sound": {"voices": 1}})").find("sound"), std::string::npos);
}

// The Shader packs tab lists folders with shaders/ in them and .zip files, each once, by name.
TEST(ShaderPackList, FoldersWithShadersAndZipsFromEveryFolderOnce) {
  const auto dir = scratchDir("shaderpack_list");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "mine" / "b-pack" / "shaders");
  std::filesystem::create_directories(dir / "mine" / "not-a-pack" / "textures");
  std::ofstream(dir / "mine" / "a.zip") << "zip";
  std::ofstream(dir / "mine" / "notes.txt") << "text";
  const std::vector<std::filesystem::path> found =
      findShaderPacks({dir / "mine", dir / "missing", dir / "mine" / ".." / "mine"});
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].filename(), "a.zip");
  EXPECT_EQ(found[1].filename(), "b-pack");
}

}  // namespace
}  // namespace terrasol
