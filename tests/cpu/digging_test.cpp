#include "digging.h"

#include <gtest/gtest.h>

#include "support/world_support.h"

namespace terrasol {
namespace {

constexpr BlockPos kAt{3, 64, -2};

struct Dug {
  int ticks = 0, hits = 0;
  bool broken = false;
};

// Holds the button on one block of `hardness` until it breaks or `limit` ticks pass.
Dug dig(float hardness, int limit = 2000) {
  Digging d;
  Dug out;
  while (out.ticks < limit && !out.broken) {
    const Digging::Tick t = d.tick(true, kAt, hardness);
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
// progress 6 / hardness / 30 a tick until it reaches 1.
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
  EXPECT_FALSE(dig(hardnessOf("bedrock")).broken) << "2000 ticks of digging leave bedrock standing";
  const Dug grass = dig(hardnessOf("short_grass"));
  EXPECT_TRUE(grass.broken);
  EXPECT_EQ(grass.ticks, 1) << "plants break at once";
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
    EXPECT_FALSE(d.tick(true, kAt, 50.0f).broken);
    ASSERT_TRUE(d.crackStage());
    EXPECT_GE(*d.crackStage(), last);
    stages += *d.crackStage() != last;
    last = *d.crackStage();
  }
  EXPECT_EQ(stages, kCrackStages);
  EXPECT_EQ(last, kCrackStages - 1);
  EXPECT_TRUE(d.tick(true, kAt, 50.0f).broken);
  EXPECT_FALSE(d.crackStage()) << "nothing left to crack";
}

// Releasing the button or looking at another block starts afresh; after a break the next block
// waits 5 ticks.
TEST(Digging, LookingAwayStartsAfreshAndABreakPauses) {
  Digging d;
  for (int i = 0; i < 7; ++i) d.tick(true, kAt, 1.5f);
  d.tick(false, kAt, 1.5f);
  EXPECT_FALSE(d.crackStage()) << "released";
  int ticks = 0;
  while (!d.tick(true, kAt, 1.5f).broken) ++ticks;
  EXPECT_EQ(ticks + 1, 8) << "the stone takes its 8 ticks again";

  const BlockPos next = kAt.offset(0, -1, 0);
  int waited = 0;
  while (!d.tick(true, next, 1.5f).hit) ++waited;
  EXPECT_EQ(waited, Digging::kDelayAfterBreak);
  for (int i = 0; i < 3; ++i) d.tick(true, next, 1.5f);
  EXPECT_EQ(d.block(), next);
  d.tick(true, kAt, 1.5f);
  EXPECT_EQ(d.block(), kAt) << "another block";
  EXPECT_EQ(d.crackStage(), 1) << "one tick's progress (0.13), not five";
  d.tick(true, std::nullopt, 1.5f);
  EXPECT_FALSE(d.block()) << "nothing in reach";
}

}  // namespace
}  // namespace terrasol
