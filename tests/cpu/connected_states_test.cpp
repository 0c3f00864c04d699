// Stairs' corner shapes from their neighbours (world/connected_states.h), as Minecraft's
// StairBlock.getStairsShape decides them.

#include "world/connected_states.h"

#include <gtest/gtest.h>

#include "support/world_support.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

World worldWithChunk() {
  World world(defaultBlocks());
  world.insertChunk(std::make_unique<Chunk>(ChunkPos{0, 0}));
  world.insertChunk(std::make_unique<Chunk>(ChunkPos{0, -1}));
  world.insertChunk(std::make_unique<Chunk>(ChunkPos{-1, 0}));
  return world;
}

std::string shapeAt(const World& world, const BlockPos& p) {
  return defaultBlocks().stateValues(connectedState(world, p, world.getBlock(p))).at("shape");
}

TEST(ConnectedStates, StairsTurnIntoCornersAgainstStairsBesideThem) {
  const BlockRegistry& b = defaultBlocks();
  World world = worldWithChunk();
  const BlockPos at{4, 64, 4};
  world.setBlock(at, b.id("oak_stairs[facing=north]"));
  EXPECT_EQ(shapeAt(world, at), "straight") << "alone";
  // A stair facing east in front of it (north): an outer corner.
  world.setBlock({4, 64, 3}, b.id("oak_stairs[facing=east]"));
  EXPECT_EQ(shapeAt(world, at), "outer_right");
  world.setBlock({4, 64, 3}, b.id("oak_stairs[facing=west]"));
  EXPECT_EQ(shapeAt(world, at), "outer_left");
  // Upside down in front: the halves differ, nothing connects.
  world.setBlock({4, 64, 3}, b.id("oak_stairs[facing=west,half=top]"));
  EXPECT_EQ(shapeAt(world, at), "straight");
  world.setBlock({4, 64, 3}, kAir);
  // Behind it (south): an inner corner.
  world.setBlock({4, 64, 5}, b.id("oak_stairs[facing=east]"));
  EXPECT_EQ(shapeAt(world, at), "inner_right");
  world.setBlock({4, 64, 5}, b.id("oak_stairs[facing=west]"));
  EXPECT_EQ(shapeAt(world, at), "inner_left");
  // Not when a stair like itself stands on the corner's side: a straight run stays straight.
  world.setBlock({3, 64, 4}, b.id("oak_stairs[facing=north]"));
  EXPECT_EQ(shapeAt(world, at), "straight");
  // Stairs facing the same way or the opposite never make a corner.
  world.setBlock({3, 64, 4}, kAir);
  world.setBlock({4, 64, 5}, b.id("oak_stairs[facing=south]"));
  EXPECT_EQ(shapeAt(world, at), "straight");
  // A block that is not a stair keeps its state.
  EXPECT_EQ(connectedState(world, at, b.id("stone")), b.id("stone"));
}

TEST(ConnectedStates, AChangeUpdatesItselfAndItsNeighbours) {
  const BlockRegistry& b = defaultBlocks();
  World world = worldWithChunk();
  world.setBlock({4, 64, 4}, b.id("oak_stairs[facing=north]"));
  world.setBlock({4, 64, 5}, b.id("oak_stairs[facing=east]"));
  const auto updates = connectionUpdates(world, {4, 64, 5});
  ASSERT_EQ(updates.size(), 1u);
  EXPECT_EQ(updates[0].first, (BlockPos{4, 64, 4}));
  EXPECT_EQ(b.stateName(updates[0].second), "oak_stairs[facing=north,half=bottom,shape=inner_right]");
  world.setBlock(updates[0].first, updates[0].second);
  EXPECT_TRUE(connectionUpdates(world, {4, 64, 5}).empty()) << "settled";
  world.setBlock({4, 64, 5}, kAir);
  const auto back = connectionUpdates(world, {4, 64, 5});
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(b.stateName(back[0].second), "oak_stairs[facing=north,half=bottom,shape=straight]");
}

}  // namespace
}  // namespace terrasol
