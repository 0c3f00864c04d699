// Light through shaped blocks: vanilla's useShapeForLightOcclusion, against hand-worked levels and
// the reference light, through the flood fill and through relighting a section.

#include <gtest/gtest.h>

#include "support/lit_world.h"
#include "support/reference_light.h"

namespace terrasol {
namespace {

using testing::compareWithReference;
using testing::defaultBlocks;
using testing::LitWorld;

// Vanilla's useShapeForLightOcclusion: light does not cross a side a slab's or stair's shape covers
// whole, in or out, and crosses every other. A closed stone room in the void gets one block of its
// roof or its north wall replaced; a torch stands two blocks north of the wall.
TEST(Light, ShapedBlocksStopLightAtTheSidesTheyCoverWhole) {
  struct Room : LitWorld {
    Room(const char* roof, const char* window) : LitWorld("void") {
      loadArea(-1, -1, 1, 1);
      fill({0, 70, 0}, {6, 74, 6}, "stone");
      fill({1, 71, 1}, {5, 73, 5}, "air");
      set({3, 74, 3}, roof);
      set({3, 72, 0}, window);
      set({3, 72, -2}, "torch");
      EXPECT_EQ(compareWithReference(world), "") << roof << ", " << window;
    }
  };
  const BlockPos roof{3, 74, 3}, belowRoof{3, 73, 3}, window{3, 72, 0}, inside{3, 72, 1};
  {
    const Room glass("glass", "glass");
    EXPECT_EQ(glass.sky(belowRoof), 15) << "glass: the open sky column goes through";
    EXPECT_EQ(glass.block(inside), 14 - 3);
  }
  {
    const Room roofSlab("stone_slab", "stone");
    EXPECT_EQ(roofSlab.sky(roof), 15) << "a bottom slab takes the sky's full light through its open top";
    EXPECT_EQ(roofSlab.sky(belowRoof), 0) << "but not out through its bottom";
    const Room windowSlab("stone", "stone_slab");
    EXPECT_EQ(windowSlab.block(window), 14 - 2) << "its sides are half open: torch light passes";
    EXPECT_EQ(windowSlab.block(inside), 14 - 3);
    EXPECT_EQ(windowSlab.sky(belowRoof), 15 - 1 - 1 - 3) << "and sky light, sideways into the room";
    // Vanilla tests the two sides together: a bottom slab's lower half and a top slab's upper half
    // close the side between them; two bottom slabs leave its upper half open.
    Room halves("stone", "stone_slab");
    halves.set(inside, "stone_slab[type=top]");
    EXPECT_EQ(halves.block(window), 14 - 2);
    EXPECT_EQ(halves.block(inside), 0) << "a top slab behind a bottom slab";
    EXPECT_EQ(halves.block({3, 72, 2}), 0);
    EXPECT_EQ(compareWithReference(halves.world), "");
    halves.set(inside, "stone_slab");
    EXPECT_EQ(halves.block(inside), 14 - 3) << "two bottom slabs";
    EXPECT_EQ(compareWithReference(halves.world), "");
  }
  {
    const Room top("stone_slab[type=top]", "stone_slab[type=double]");
    EXPECT_EQ(top.sky(roof), 0) << "a top slab's covered top keeps sky light out of it";
    EXPECT_EQ(top.sky(belowRoof), 0);
    EXPECT_EQ(top.block(window), 0) << "a double slab is closed on every side";
    EXPECT_EQ(top.block(inside), 0);
  }
  {
    const Room back("stone", "oak_stairs[facing=north]");
    EXPECT_EQ(back.block(window), 0) << "stairs facing the torch turn their closed back to it";
    EXPECT_EQ(back.block(inside), 0);
    const Room side("stone", "oak_stairs[facing=east]");
    EXPECT_EQ(side.block(window), 14 - 2) << "stairs facing east: their north and south sides are L-shaped";
    EXPECT_EQ(side.block(inside), 14 - 3);
  }
}

// A glass window swapped for a double slab (closed on every side) without the light engine hearing of
// it: relighting its section takes the light out of the room behind it.
TEST(Light, RelightingASectionKnowsItsShapedBlocks) {
  LitWorld w("void");
  w.loadArea(-1, -1, 1, 1);
  w.fill({0, 70, 0}, {6, 74, 6}, "stone");
  w.fill({1, 71, 1}, {5, 73, 5}, "air");
  w.set({3, 72, 0}, "glass");
  w.set({3, 72, -2}, "torch");
  ASSERT_EQ(w.block({3, 72, 1}), 11);
  ASSERT_TRUE(w.world.setBlock({3, 72, 0}, defaultBlocks().id("stone_slab[type=double]")));
  w.light.relightSection({0, sectionOf(72), 0});
  EXPECT_EQ(w.block({3, 72, 1}), 0);
  EXPECT_EQ(w.sky({3, 72, 1}), 0);
  EXPECT_EQ(compareWithReference(w.world), "");
}

// A waterlogged cell filters light as water does: in a shaft through stone, sky light loses a level
// in each of a column of waterlogged glass panes, and none through dry ones.
TEST(Light, WaterloggedBlocksFilterLightAsWater) {
  LitWorld w("void");
  w.loadArea(-1, -1, 1, 1);
  w.fill({0, 66, 0}, {5, 72, 2}, "stone");
  for (int y = 66; y <= 72; ++y) {
    w.set({1, y, 1}, y >= 70 ? "glass_pane[waterlogged=true]" : "air");
    w.set({4, y, 1}, y >= 70 ? "glass_pane[waterlogged=false]" : "air");
  }
  EXPECT_EQ(w.sky({1, 72, 1}), 14);
  EXPECT_EQ(w.sky({1, 71, 1}), 13);
  EXPECT_EQ(w.sky({1, 70, 1}), 12);
  EXPECT_EQ(w.sky({1, 69, 1}), 11) << "below, what is left of the sky steps down as everywhere";
  EXPECT_EQ(w.sky({4, 70, 1}), 15);
  EXPECT_EQ(w.sky({4, 66, 1}), 15);
  EXPECT_EQ(compareWithReference(w.world), "");
}

}  // namespace
}  // namespace terrasol
