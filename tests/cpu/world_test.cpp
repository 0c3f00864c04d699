#include "world/world.h"

#include <gtest/gtest.h>

#include "support/world_support.h"
#include "world/generator.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

TEST(Section, UniformSectionsCostNoBlockMemory) {
  Section s;
  EXPECT_TRUE(s.isAllAir());
  EXPECT_EQ(s.memoryBytes(), 0u);
  EXPECT_EQ(s.set(1, 2, 3, kAir), kAir);  // writing the same block keeps it uniform
  EXPECT_EQ(s.memoryBytes(), 0u);
  EXPECT_EQ(s.set(1, 2, 3, 5), kAir);
  EXPECT_EQ(s.memoryBytes(), 8192u);
  EXPECT_EQ(s.get(1, 2, 3), 5);
  EXPECT_EQ(s.get(2, 2, 3), kAir);
  EXPECT_FALSE(s.compact());
  EXPECT_EQ(s.set(1, 2, 3, kAir), 5);
  EXPECT_TRUE(s.compact());
  EXPECT_EQ(s.memoryBytes(), 0u);
  Section copy = s;
  copy.fill(7);
  EXPECT_EQ(copy.get(15, 15, 15), 7);
  EXPECT_EQ(s.get(15, 15, 15), kAir);
}

TEST(Chunk, EmptyChunkHoldsNoBlockArrays) {
  Chunk c({0, 0});
  EXPECT_EQ(c.memoryBytes(), sizeof(Chunk));
  EXPECT_EQ(c.get(0, kMinY - 1, 0), kAir);  // outside the height: air, never a crash
  EXPECT_EQ(c.set(0, kMaxY, 0, 3), kAir);
  EXPECT_EQ(c.get(0, kMaxY, 0), kAir);
}

// Runs the same edits around `origin` and returns what the world reports.
std::vector<std::string> editsAround(const BlockPos& origin) {
  const BlockRegistry& blocks = defaultBlocks();
  World world(blocks);
  const ChunkPos center = ChunkPos::of(origin);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx)
      world.insertChunk(std::make_unique<Chunk>(ChunkPos{center.x + dx, center.z + dz}));
  std::vector<std::string> log;
  const BlockId stone = blocks.id("stone"), torch = blocks.id("torch");
  // Local offsets spanning chunk and section borders in every direction.
  const int offsets[][3] = {{0, 0, 0},    {-1, 0, 0},     {15, 15, 15},
                            {16, 16, 16}, {-16, -1, -17}, {5, 320 - 70, 5}};
  for (const auto& o : offsets) {
    const BlockPos p = origin.offset(o[0], o[1], o[2]);
    auto change = world.setBlock(p, stone);
    log.push_back(change ? std::to_string(change->before) + ">" + std::to_string(change->after) : "none");
    log.push_back(std::to_string(world.getBlock(p)));
    log.push_back(std::to_string(world.neighbour(p, Direction::East)) + "," +
                  std::to_string(world.neighbour(p, Direction::Down)));
    log.push_back(world.setBlock(p, stone) ? "changed again" : "unchanged");
    world.setBlock(p.offset(1, 0, 0), torch);
    log.push_back(std::to_string(world.neighbour(p, Direction::East)));
  }
  log.push_back(world.setBlock(origin.offset(40, 0, 0), stone) ? "unloaded changed" : "unloaded none");
  return log;
}

TEST(World, EditsAcrossBordersAreReportedAndReadBack) {
  const auto log = editsAround({0, 64, 0});
  EXPECT_EQ(log[0], "0>1");  // air -> stone
  EXPECT_EQ(log[1], "1");
  EXPECT_EQ(log[3], "unchanged");
  EXPECT_EQ(log[4], std::to_string(defaultBlocks().id("torch")));
  EXPECT_EQ(log.back(), "unloaded none");
}

TEST(World, FarFromTheOriginBehavesExactlyLikeTheOrigin) {
  // Same position inside its chunk (29 999 000 = 16 * 1 874 937 + 8), so the same edits cross the same
  // borders.
  EXPECT_EQ(editsAround({8, 64, 8}), editsAround({29'999'000, 64, 29'999'000}));
  EXPECT_EQ(editsAround({0, 64, 0}), editsAround({-29'999'008, 64, -29'999'008}));
  EXPECT_EQ(ChunkPos::of({-29'999'999, 0, 29'999'999}).x, -1'875'000);
  EXPECT_EQ(localOf(-29'999'999), 1);
}

TEST(World, OutsideHeightAndBorderNothingHappens) {
  World world(defaultBlocks());
  world.insertChunk(std::make_unique<Chunk>(ChunkPos{0, 0}));
  EXPECT_FALSE(world.setBlock({0, kMaxY, 0}, 1));
  EXPECT_FALSE(world.setBlock({0, kMinY - 1, 0}, 1));
  EXPECT_EQ(world.getBlock({0, 100000, 0}), kAir);
  EXPECT_EQ(world.getBlock({kWorldBorder, 0, 0}), kAir);
  EXPECT_TRUE(world.setBlock({0, kMinY, 0}, 1));
  EXPECT_TRUE(world.setBlock({0, kMaxY - 1, 0}, 1));
}

}  // namespace
}  // namespace terrasol
