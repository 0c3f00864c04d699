#include "digging.h"

#include <gtest/gtest.h>

#include "support/world_support.h"

namespace terrasol {
namespace {

constexpr BlockPos kAt{3, 64, -2};

DigInput input(bool click, bool hold, const std::optional<BlockPos>& at, float hardness) {
  DigInput in;
  in.clicked = click;
  in.held = hold;
  in.target = at;
  in.hardness = hardness;
  return in;
}
// The button held on `at` (clicked down this tick when `click`).
DigInput held(const std::optional<BlockPos>& at, float hardness, bool click = false) {
  return input(click, true, at, hardness);
}

struct Dug {
  int ticks = 0, hits = 0;
  bool broken = false;
};

// Clicks on one block of `hardness` and holds until it breaks or `limit` ticks pass.
Dug dig(float hardness, bool hampered = false, int limit = 5000) {
  Digging d;
  Dug out;
  while (out.ticks < limit && !out.broken) {
    DigInput in = held(kAt, hardness, out.ticks == 0);
    in.hampered = hampered;
    const Digging::Tick t = d.tick(in);
    ++out.ticks;
    out.hits += t.hit;
    out.broken = t.broken;
  }
  return out;
}

float hardnessOf(const char* block) {
  const BlockRegistry& b = testing::defaultBlocks();
  return b[b.id(block)].hardness;
}

// Minecraft's hardness from its block table, and the ticks it takes with an iron tool's speed (6):
// progress 6 / hardness / 30 a tick from the click until it reaches 1; 5 times slower off the ground
// or under water.
TEST(Digging, BlocksTakeMinecraftsTimeForTheirHardness) {
  EXPECT_EQ(hardnessOf("stone"), 1.5f);
  EXPECT_EQ(hardnessOf("dirt"), 0.5f);
  EXPECT_EQ(hardnessOf("obsidian"), 50.0f);
  EXPECT_EQ(hardnessOf("bedrock"), kUnbreakable);
  EXPECT_EQ(hardnessOf("short_grass"), 0.0f);
  EXPECT_EQ(dig(hardnessOf("stone")).ticks, 8);
  EXPECT_EQ(dig(hardnessOf("dirt")).ticks, 3);
  EXPECT_EQ(dig(hardnessOf("oak_log")).ticks, 10);
  EXPECT_EQ(dig(hardnessOf("obsidian")).ticks, 250);
  EXPECT_EQ(dig(hardnessOf("stone"), true).ticks, 38) << "hampered: 7.5 x 5 ticks";
  EXPECT_FALSE(dig(hardnessOf("bedrock")).broken) << "5000 ticks of digging leave bedrock standing";
  const Dug grass = dig(hardnessOf("short_grass"), true);
  EXPECT_TRUE(grass.broken);
  EXPECT_EQ(grass.ticks, 1) << "plants break at the click, even in the air";
  EXPECT_EQ(grass.hits, 0) << "and make no hit sound";
}

// The hit sound on the first tick and every 4th after, the crack through its 10 stages in order.
TEST(Digging, HitsEveryFourthTickAndTheCrackGrows) {
  EXPECT_EQ(dig(1.5f).hits, 2) << "ticks 1 and 5 of 8";
  EXPECT_EQ(dig(50.0f).hits, 63) << "ticks 1, 5, ..., 249 of 250";
  Digging d;
  EXPECT_FALSE(d.crackStage());
  int last = -1, stages = 0;
  for (int i = 0; i < 249; ++i) {
    EXPECT_FALSE(d.tick(held(kAt, 50.0f, i == 0)).broken);
    ASSERT_TRUE(d.crackStage());
    EXPECT_GE(*d.crackStage(), last);
    stages += *d.crackStage() != last;
    last = *d.crackStage();
  }
  EXPECT_EQ(stages, kCrackStages);
  EXPECT_EQ(last, kCrackStages - 1);
  EXPECT_TRUE(d.tick(held(kAt, 50.0f)).broken);
  EXPECT_FALSE(d.crackStage()) << "nothing left to crack";
}

// Letting go stops; a click released within its tick digs nothing (but breaks a plant); holding onto
// another block starts on it with a tick that adds nothing; after a break the next block waits 5 held
// ticks, however long the button was up.
TEST(Digging, StartsStopsAndPausesAsMinecraftDoes) {
  Digging d;
  for (int i = 0; i < 7; ++i) d.tick(held(kAt, 1.5f, i == 0));
  d.tick(input(false, false, kAt, 1.5f));
  EXPECT_FALSE(d.crackStage()) << "let go";
  EXPECT_FALSE(d.tick(input(true, false, kAt, 1.5f)).hit) << "a quick click";
  EXPECT_FALSE(d.block());
  EXPECT_TRUE(d.tick(input(true, false, kAt, 0.0f)).broken) << "a plant";

  int ticks = 1;
  for (bool click = true; !d.tick(held(kAt, 1.5f, click)).broken; click = false) ++ticks;
  EXPECT_EQ(ticks, 8) << "the stone takes its 8 ticks again";
  const BlockPos next = kAt.offset(0, -1, 0);
  for (int i = 0; i < 20; ++i) d.tick(input(false, false, next, 1.5f));  // the button up
  int waited = 0;
  for (bool click = true; !d.tick(held(next, 1.5f, click)).hit; click = false) ++waited;
  EXPECT_EQ(waited, Digging::kDelayAfterBreak) << "the click starts the block, the pause then runs out";

  for (int i = 0; i < 3; ++i) d.tick(held(next, 1.5f));
  EXPECT_EQ(d.block(), next);
  EXPECT_TRUE(d.crackStage());
  EXPECT_FALSE(d.tick(held(kAt, 1.5f)).hit) << "held onto another block: started, not hit";
  EXPECT_EQ(d.block(), kAt);
  EXPECT_FALSE(d.crackStage()) << "no progress yet";
  EXPECT_TRUE(d.tick(held(kAt, 1.5f)).hit);
  d.tick(held(std::nullopt, 1.5f));
  EXPECT_FALSE(d.block()) << "nothing in reach";
}

}  // namespace
}  // namespace terrasol
