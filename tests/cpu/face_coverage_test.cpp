// What a shaped block covers of its cell's sides (world/face_coverage.h), and so which neighbouring
// faces it hides: slabs, stairs, a carpet, against each other and against full cubes.

#include "world/face_coverage.h"

#include <gtest/gtest.h>

#include <vector>

namespace terrasol {
namespace {

const ShapeBox kBottomSlab{{0, 0, 0}, {16, 8, 16}};
const ShapeBox kTopSlab{{0, 8, 0}, {16, 16, 16}};
// A bottom stair facing east (its tall back at the east): a bottom slab and the upper east half.
const std::vector<ShapeBox> kStairEast = {kBottomSlab, {{8, 8, 0}, {16, 16, 16}}};
const ShapeBox kCarpet{{0, 0, 0}, {16, 1, 16}};

FaceCoverage cover(std::vector<ShapeBox> boxes) {
  return FaceCoverage::of(boxes);
}

constexpr SideRect kWhole{};
constexpr SideRect kLowerHalfOfASide{0, 0, 8, 16};  // west/east sides: a = y, b = z

TEST(FaceCoverage, ABottomSlabCoversItsBottomAndTheLowerHalfOfItsSides) {
  const FaceCoverage slab = cover({kBottomSlab});
  EXPECT_TRUE(slab.full(Direction::Down));
  EXPECT_TRUE(slab.empty(Direction::Up)) << "its top is open";
  for (Direction side : {Direction::West, Direction::East}) {
    EXPECT_TRUE(slab.covers(side, kLowerHalfOfASide));
    EXPECT_FALSE(slab.covers(side, kWhole));
    EXPECT_FALSE(slab.covers(side, {8, 0, 16, 16}));
  }
  EXPECT_TRUE(slab.covers(Direction::North, {0, 0, 16, 8})) << "north/south: a = x, b = y";
  EXPECT_FALSE(slab.covers(Direction::North, {0, 8, 16, 16}));
}

TEST(FaceCoverage, NeighboursHideOnlyTheFacesTheyCover) {
  const FaceCoverage slab = cover({kBottomSlab}), top = cover({kTopSlab}), cube = FaceCoverage::fullCube(),
                     air;
  // A block above a bottom slab keeps its bottom face (the slab's top is open); above a top slab, not.
  EXPECT_FALSE(hiddenBy(slab, Direction::Down, kWhole)) << "seen through the slab's open top half";
  EXPECT_TRUE(hiddenBy(top, Direction::Down, kWhole)) << "a top slab's top is whole";
  // Two bottom slabs side by side hide each other's touching halves.
  EXPECT_TRUE(hiddenBy(slab, Direction::East, kLowerHalfOfASide));
  // A slab's side against a full cube is hidden; a full cube's side against a slab is not.
  EXPECT_TRUE(hiddenBy(cube, Direction::East, kLowerHalfOfASide));
  EXPECT_FALSE(hiddenBy(slab, Direction::East, kWhole));
  // A bottom slab next to a top slab: their halves do not meet.
  EXPECT_FALSE(hiddenBy(top, Direction::East, kLowerHalfOfASide));
  EXPECT_FALSE(hiddenBy(air, Direction::Up, {0, 0, 1, 1}));
}

TEST(FaceCoverage, StairsCoverTheirBackAndBottomWholeAndHalfOfTheOthers) {
  const FaceCoverage stair = cover(kStairEast);
  EXPECT_TRUE(stair.full(Direction::Down));
  EXPECT_TRUE(stair.full(Direction::East)) << "the tall back";
  EXPECT_FALSE(stair.full(Direction::West));
  EXPECT_TRUE(stair.covers(Direction::West, kLowerHalfOfASide));
  EXPECT_TRUE(stair.covers(Direction::Up, {8, 0, 16, 16})) << "up: a = x, b = z; the back half's top";
  EXPECT_FALSE(stair.covers(Direction::Up, {0, 0, 8, 16})) << "the step's top lies at y = 8, inside";
  EXPECT_TRUE(stair.covers(Direction::North, {0, 0, 16, 8}));
  EXPECT_TRUE(stair.covers(Direction::North, {8, 8, 16, 16}));
  EXPECT_FALSE(stair.covers(Direction::North, {0, 8, 8, 16}));
}

TEST(FaceCoverage, ACarpetCoversItsBottomAndASliverOfItsSides) {
  const FaceCoverage carpet = cover({kCarpet});
  EXPECT_TRUE(carpet.full(Direction::Down));
  EXPECT_TRUE(carpet.empty(Direction::Up));
  EXPECT_TRUE(carpet.covers(Direction::South, {0, 0, 16, 1}));
  EXPECT_FALSE(carpet.covers(Direction::South, {0, 0, 16, 2}));
}

}  // namespace
}  // namespace terrasol
