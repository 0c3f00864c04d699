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
  EXPECT_EQ(b.stateName(updates[0].second),
            "oak_stairs[facing=north,half=bottom,shape=inner_right,waterlogged=false]");
  world.setBlock(updates[0].first, updates[0].second);
  EXPECT_TRUE(connectionUpdates(world, {4, 64, 5}).empty()) << "settled";
  world.setBlock({4, 64, 5}, kAir);
  const auto back = connectionUpdates(world, {4, 64, 5});
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(b.stateName(back[0].second),
            "oak_stairs[facing=north,half=bottom,shape=straight,waterlogged=false]");
}

// Fences join fences, gates across their line and whole faces; panes join panes, walls and whole
// faces (glass too, leaves not); walls join walls and panes, rise tall under a whole bottom and drop
// their post where they run straight.
TEST(ConnectedStates, FencesPanesAndWallsJoinTheirKindAndWholeFaces) {
  const BlockRegistry& b = defaultBlocks();
  World world(b, &testing::handShapes());
  world.insertChunk(std::make_unique<Chunk>(ChunkPos{0, 0}));
  const auto stateAt = [&](const BlockPos& p) {
    return b.stateName(connectedState(world, p, world.getBlock(p)));
  };
  const BlockPos fence{4, 64, 4};
  world.setBlock(fence, b.id("oak_fence"));
  EXPECT_EQ(stateAt(fence), "oak_fence[east=false,north=false,south=false,waterlogged=false,west=false]")
      << "alone: a post";
  world.setBlock({5, 64, 4}, b.id("oak_fence"));
  world.setBlock({4, 64, 3}, b.id("stone"));
  world.setBlock({3, 64, 4}, b.id("stone_slab"));
  world.setBlock({4, 64, 5}, b.id("glass_pane"));
  EXPECT_EQ(stateAt(fence), "oak_fence[east=true,north=true,south=false,waterlogged=false,west=false]")
      << "a fence and stone; not half a side, nor a pane";
  world.setBlock({3, 64, 4}, b.id("stone_slab[type=double]"));
  world.setBlock({4, 64, 5}, b.id("oak_fence_gate[facing=east]"));
  EXPECT_EQ(stateAt(fence), "oak_fence[east=true,north=true,south=true,waterlogged=false,west=true]")
      << "a double slab, and a gate whose bars run north-south";
  world.setBlock({4, 64, 5}, b.id("oak_fence_gate[facing=south]"));
  EXPECT_EQ(stateAt(fence), "oak_fence[east=true,north=true,south=false,waterlogged=false,west=true]")
      << "not one across";

  const BlockPos pane{10, 64, 10};
  world.setBlock(pane, b.id("glass_pane"));
  world.setBlock({11, 64, 10}, b.id("glass"));
  world.setBlock({9, 64, 10}, b.id("oak_leaves"));
  world.setBlock({10, 64, 9}, b.id("cobblestone_wall"));
  world.setBlock({10, 64, 11}, b.id("oak_fence"));
  EXPECT_EQ(stateAt(pane), "glass_pane[east=true,north=true,south=false,waterlogged=false,west=false]")
      << "glass and a wall; not leaves, nor a fence";

  const BlockPos wall{4, 64, 12};
  world.setBlock(wall, b.id("cobblestone_wall"));
  world.setBlock({4, 64, 11}, b.id("cobblestone_wall"));
  world.setBlock({4, 64, 13}, b.id("glass_pane"));
  EXPECT_EQ(stateAt(wall),
            "cobblestone_wall[east=none,north=low,south=low,up=false,waterlogged=false,west=none]")
      << "straight through: no post";
  world.setBlock({4, 65, 12}, b.id("stone"));
  EXPECT_EQ(stateAt(wall),
            "cobblestone_wall[east=none,north=tall,south=tall,up=false,waterlogged=false,west=none]")
      << "under stone";
  world.setBlock({5, 64, 12}, b.id("stone"));
  EXPECT_EQ(stateAt(wall),
            "cobblestone_wall[east=tall,north=tall,south=tall,up=true,waterlogged=false,west=none]")
      << "a T: a post";

  // Changes reach the neighbours and the wall below.
  world.setBlock({4, 65, 12}, kAir);
  const auto updates = connectionUpdates(world, {4, 65, 12});
  ASSERT_EQ(updates.size(), 1u);
  EXPECT_EQ(updates[0].first, wall);
}

}  // namespace
}  // namespace terrasol
