// Block picking and placement in the game: the crosshair's target (shaped blocks by their boxes),
// Minecraft's placement rules, and using doors, gates and trapdoors.

#include "placement.h"

#include <gtest/gtest.h>

#include "support/game_world.h"
#include "targeting.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;
using testing::defaultShapes;
using testing::flatWorld;

// The placed cells' states, as Minecraft names them, space-separated.
std::string stateNames(const BlockRegistry& blocks, const std::vector<Placement>& cells) {
  std::string out;
  for (const Placement& p : cells) {
    if (!out.empty()) out += ' ';
    out += blocks.stateName(p.state);
  }
  return out;
}

TEST(TargetingTest, PicksTheFirstBlockAndTheFaceWithinReach) {
  World world = flatWorld();
  const auto hit = targetBlock(world, {0.5, 65.62, 0.5}, {0.0, -1.0, 0.0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->block, (BlockPos{0, 63, 0}));
  EXPECT_EQ(hit->normal, glm::ivec3(0, 1, 0));
  EXPECT_EQ(hit->place, (BlockPos{0, 64, 0}));
  EXPECT_FALSE(targetBlock(world, {0.5, 70.0, 0.5}, {0.0, -1.0, 0.0})) << "6 blocks is out of reach";
  world.setBlock({0, 64, 0}, defaultBlocks().id("water"));
  const auto throughWater = targetBlock(world, {0.5, 65.62, 0.5}, {0.0, -1.0, 0.0});
  ASSERT_TRUE(throughWater);
  EXPECT_EQ(throughWater->block, (BlockPos{0, 63, 0})) << "water is not targeted";
  EXPECT_FALSE(targetBlock(world, {0.5, 65.62, 0.5}, {0.0, 0.0, 0.0})) << "no direction, no target";
}

// Minecraft's placement rules: slabs by the clicked face and height, two slabs joined into one double
// slab, stairs facing the way the player looks and upside down against a ceiling or a side's upper half.
TEST(PlacementTest, SlabsAndStairsTakeTheirStateFromWhereAndHowTheyArePlaced) {
  World world = flatWorld();
  const BlockRegistry& b = defaultBlocks();
  const BlockId slab = b.id("stone_slab"), stairs = b.id("oak_stairs");
  const Target floor{{0, 63, 0}, {0, 1, 0}, {0, 64, 0}, 1.0};
  const glm::dvec3 south(0.0, -0.5, 1.0), west(-1.0, -0.2, 0.1);
  const auto one = [&](const std::vector<Placement>& cells) {
    EXPECT_EQ(cells.size(), 1u);
    return cells.empty() ? Placement{} : cells[0];
  };
  const auto name = [&](const std::vector<Placement>& cells) { return b.stateName(one(cells).state); };
  EXPECT_EQ(name(placementOf(world, slab, floor, floor.place, {0.5, 64.0, 0.5}, south)),
            "stone_slab[type=bottom,waterlogged=false]");
  // On a wall's side, above or below its middle.
  const Target side{{0, 64, 3}, {0, 0, -1}, {0, 64, 2}, 2.0};
  EXPECT_EQ(name(placementOf(world, slab, side, side.place, {0.5, 64.7, 3.0}, south)),
            "stone_slab[type=top,waterlogged=false]");
  EXPECT_EQ(name(placementOf(world, slab, side, side.place, {0.5, 64.3, 3.0}, south)),
            "stone_slab[type=bottom,waterlogged=false]");
  // Against a ceiling.
  const Target ceiling{{0, 70, 0}, {0, -1, 0}, {0, 69, 0}, 2.0};
  EXPECT_EQ(name(placementOf(world, slab, ceiling, ceiling.place, {0.5, 70.0, 0.5}, south)),
            "stone_slab[type=top,waterlogged=false]");
  EXPECT_EQ(name(placementOf(world, stairs, ceiling, ceiling.place, {0.5, 70.0, 0.5}, south)),
            "oak_stairs[facing=south,half=top,shape=straight,waterlogged=false]");
  // Clicking a bottom slab's top joins them where it is; its side does not.
  world.setBlock({0, 64, 0}, slab);
  const Target onSlab{{0, 64, 0}, {0, 1, 0}, {0, 65, 0}, 1.0};
  const Placement joined = one(placementOf(world, slab, onSlab, onSlab.place, {0.5, 64.5, 0.5}, south));
  EXPECT_EQ(joined.at, (BlockPos{0, 64, 0}));
  EXPECT_EQ(b.stateName(joined.state), "stone_slab[type=double,waterlogged=false]");
  const Target slabSide{{0, 64, 0}, {0, 0, 1}, {0, 64, 1}, 1.0};
  EXPECT_EQ(one(placementOf(world, slab, slabSide, slabSide.place, {0.5, 64.2, 1.0}, south)).at,
            (BlockPos{0, 64, 1}));
  // Stairs face the way the player looks.
  EXPECT_EQ(name(placementOf(world, stairs, floor, floor.place, {0.5, 64.0, 0.5}, south)),
            "oak_stairs[facing=south,half=bottom,shape=straight,waterlogged=false]");
  EXPECT_EQ(name(placementOf(world, stairs, floor, floor.place, {0.5, 64.0, 0.5}, west)),
            "oak_stairs[facing=west,half=bottom,shape=straight,waterlogged=false]");
  // A block without a placement rule keeps its state.
  EXPECT_EQ(one(placementOf(world, b.id("stone"), side, side.place, {0.5, 64.7, 3.0}, south)).state,
            b.id("stone"));
}

// The other rules: logs along the clicked face's axis, furnaces facing the player, snow piling up,
// ladders and wall torches only on a wall's side, trapdoors on a side's half, doors in two cells
// with the hinge away from a wall beside them.
TEST(PlacementTest, EveryRuleOfThePack) {
  World world = flatWorld();
  world.setShapes(&defaultShapes());
  const BlockRegistry& b = defaultBlocks();
  const glm::dvec3 south(0.0, -0.5, 1.0);
  const auto names = [&](const std::vector<Placement>& cells) { return stateNames(b, cells); };
  const Target floor{{0, 63, 0}, {0, 1, 0}, {0, 64, 0}, 1.0};
  const Target wallSide{{0, 64, 3}, {0, 0, -1}, {0, 64, 2}, 2.0};  // the north side of stone at z 3
  world.setBlock({0, 64, 3}, b.id("stone"));
  const auto place = [&](const char* block, const Target& t, glm::dvec3 hit) {
    return names(placementOf(world, b.id(block), t, t.place, hit, south));
  };
  EXPECT_EQ(place("oak_log", floor, {0.5, 64.0, 0.5}), "oak_log[axis=y]");
  EXPECT_EQ(place("oak_log", wallSide, {0.5, 64.5, 3.0}), "oak_log[axis=z]");
  EXPECT_EQ(place("furnace", floor, {0.5, 64.0, 0.5}), "furnace[facing=north,lit=false]")
      << "its front to the player";
  EXPECT_EQ(place("oak_fence_gate", floor, {0.5, 64.0, 0.5}),
            "oak_fence_gate[facing=south,in_wall=false,open=false,powered=false]");
  EXPECT_EQ(place("ladder", wallSide, {0.5, 64.5, 3.0}), "ladder[facing=north,waterlogged=false]");
  EXPECT_EQ(place("ladder", floor, {0.5, 64.0, 0.5}), "") << "not on a floor";
  EXPECT_EQ(place("torch", wallSide, {0.5, 64.5, 3.0}), "wall_torch[facing=north]");
  EXPECT_EQ(place("torch", floor, {0.5, 64.0, 0.5}), "torch");
  EXPECT_EQ(place("oak_trapdoor", wallSide, {0.5, 64.8, 3.0}),
            "oak_trapdoor[facing=north,half=top,open=false,powered=false,waterlogged=false]");
  EXPECT_EQ(place("oak_trapdoor", floor, {0.5, 64.0, 0.5}),
            "oak_trapdoor[facing=north,half=bottom,open=false,powered=false,waterlogged=false]");
  world.setBlock({0, 64, 0}, b.id("snow"));
  const Target onSnow{{0, 64, 0}, {0, 1, 0}, {0, 65, 0}, 1.0};
  EXPECT_EQ(place("snow", onSnow, {0.5, 64.125, 0.5}), "snow[layers=2]");
  // A door facing south: its left is east, as Minecraft turns south anticlockwise. Its hinge goes
  // against a wall beside it, and away from a door it pairs with.
  const Target ground{{5, 63, 5}, {0, 1, 0}, {5, 64, 5}, 1.0};
  const auto hinge = [&] {
    const std::string both = place("oak_door", ground, {5.5, 64.0, 5.5});
    const auto at = both.find("hinge=");
    return both.substr(at + 6, both.find(',', at) - at - 6);
  };
  world.setBlock({6, 64, 5}, b.id("stone"));
  EXPECT_EQ(place("oak_door", ground, {5.5, 64.0, 5.5}),
            "oak_door[facing=south,half=lower,hinge=left,open=false,powered=false] "
            "oak_door[facing=south,half=upper,hinge=left,open=false,powered=false]");
  world.setBlock({6, 64, 5}, kAir);
  world.setBlock({4, 64, 5}, b.id("stone"));
  EXPECT_EQ(hinge(), "right") << "stone on its right (west)";
  world.setBlock({4, 64, 5}, b.id("oak_door[facing=south,half=lower,hinge=left,open=false,powered=false]"));
  EXPECT_EQ(hinge(), "left") << "a door on its right: the pair's hinges on the outer sides";
  world.setBlock({4, 64, 5}, kAir);
  EXPECT_EQ(hinge(), "left") << "alone, clicked on the cell's west half (x 0.5 counts as the left)";
}

// Minecraft's blocks blocks.json gives no rule follow the rule their properties imply: pointing out
// of the clicked face, on a floor, wall or ceiling, turned toward the player or on a wall as their wall
// form, two cells high or long (and broken whole), rails on a whole block only.
TEST(PlacementTest, MinecraftsFamiliesByTheirProperties) {
  World world = flatWorld();
  world.setShapes(&defaultShapes());
  const BlockRegistry& b = defaultBlocks();
  const glm::dvec3 east(1.0, -0.5, 0.0);
  const auto names = [&](const std::vector<Placement>& cells) { return stateNames(b, cells); };
  const Target floor{{0, 63, 0}, {0, 1, 0}, {0, 64, 0}, 1.0};
  const Target ceiling{{0, 66, 0}, {0, -1, 0}, {0, 65, 0}, 1.0};
  const Target wallSide{{0, 64, 3}, {0, 0, -1}, {0, 64, 2}, 2.0};  // the north side of stone at z 3
  world.setBlock({0, 64, 3}, b.id("stone"));
  const auto place = [&](const char* block, const Target& t, glm::dvec3 look = {0.0, -0.5, 1.0}) {
    return names(placementOf(world, b.id(block), t, t.place,
                             {t.place.x + 0.5, t.place.y + 0.5, t.place.z + 0.5}, look));
  };
  EXPECT_EQ(place("end_rod", wallSide), "end_rod[facing=north]");
  EXPECT_EQ(place("piston", floor), "piston[extended=false,facing=up]");
  EXPECT_EQ(place("hopper", wallSide), "hopper[enabled=true,facing=south]") << "into the block it is put on";
  EXPECT_EQ(place("stone_button", wallSide), "stone_button[face=wall,facing=north,powered=false]");
  EXPECT_EQ(place("lever", ceiling, east), "lever[face=ceiling,facing=east,powered=false]");
  EXPECT_EQ(place("oak_sign", floor), "oak_sign[rotation=8,waterlogged=false]") << "facing the player";
  EXPECT_EQ(place("oak_sign", floor, east), "oak_sign[rotation=4,waterlogged=false]");
  EXPECT_EQ(place("oak_sign", wallSide), "oak_wall_sign[facing=north,waterlogged=false]");
  EXPECT_EQ(place("creeper_head", wallSide), "creeper_wall_head[facing=north,powered=false]");
  EXPECT_EQ(place("tube_coral_fan", wallSide), "tube_coral_wall_fan[facing=north,waterlogged=false]");
  EXPECT_EQ(place("tube_coral_fan", floor), "tube_coral_fan[waterlogged=false]");
  EXPECT_EQ(place("sunflower", floor), "sunflower[half=lower] sunflower[half=upper]");
  EXPECT_EQ(place("red_bed", floor, east),
            "red_bed[facing=east,occupied=false,part=foot] red_bed[facing=east,occupied=false,part=head]");
  EXPECT_EQ(place("rail", floor, east), "rail[shape=east_west,waterlogged=false]");
  world.setBlock({0, 70, 3}, b.id("stone"));
  const Target highSide{{0, 70, 3}, {0, 0, -1}, {0, 70, 2}, 2.0};
  EXPECT_EQ(place("rail", highSide), "") << "nothing below it";
  EXPECT_EQ(place("ochre_froglight", wallSide), "ochre_froglight[axis=z]");
  // Broken whole: a bed's head takes its foot, a tall flower's top its bottom.
  world.setBlock({2, 64, 0}, b.id("red_bed[facing=east,occupied=false,part=foot]"));
  world.setBlock({3, 64, 0}, b.id("red_bed[facing=east,occupied=false,part=head]"));
  EXPECT_EQ(brokenBy(world, {3, 64, 0}).size(), 2u);
  world.setBlock({5, 64, 0}, b.id("sunflower[half=lower]"));
  world.setBlock({5, 65, 0}, b.id("sunflower[half=upper]"));
  EXPECT_EQ(brokenBy(world, {5, 65, 0}).size(), 2u);
  // Wall forms are placed through their standing block, not offered on their own.
  EXPECT_EQ(pickedBy(world, {0, 64, 3}), b.id("stone"));
  world.setBlock({0, 64, 2}, b.id("oak_wall_sign[facing=north,waterlogged=false]"));
  EXPECT_EQ(pickedBy(world, {0, 64, 2}), b.id("oak_sign"));
}

// Right-clicking a door opens both its halves, a gate opened from its far side turns to swing away,
// breaking either half of a door takes both, and other blocks are not used.
TEST(PlacementTest, DoorsGatesAndTrapdoorsOpenAndClose) {
  World world = flatWorld();
  const BlockRegistry& b = defaultBlocks();
  world.setBlock({0, 64, 0}, b.id("oak_door[facing=south,half=lower,hinge=left,open=false,powered=false]"));
  world.setBlock({0, 65, 0}, b.id("oak_door[facing=south,half=upper,hinge=left,open=false,powered=false]"));
  const auto used = useOf(world, {0, 65, 0}, {0.0, 0.0, 1.0});
  ASSERT_EQ(used.size(), 2u);
  EXPECT_EQ(b.stateName(used[0].state),
            "oak_door[facing=south,half=upper,hinge=left,open=true,powered=false]");
  EXPECT_EQ(used[1].at, (BlockPos{0, 64, 0}));
  EXPECT_EQ(b.stateName(used[1].state),
            "oak_door[facing=south,half=lower,hinge=left,open=true,powered=false]");
  EXPECT_EQ(brokenBy(world, {0, 64, 0}).size(), 2u);
  world.setBlock({3, 64, 0}, b.id("oak_fence_gate[facing=south,in_wall=false,open=false,powered=false]"));
  const auto gate = useOf(world, {3, 64, 0}, {0.0, 0.0, -1.0});
  ASSERT_EQ(gate.size(), 1u);
  EXPECT_EQ(b.stateName(gate[0].state), "oak_fence_gate[facing=north,in_wall=false,open=true,powered=false]")
      << "opened from the south";
  world.setBlock({5, 64, 0}, b.id("oak_trapdoor"));
  EXPECT_EQ(b.stateName(useOf(world, {5, 64, 0}, {0.0, 0.0, 1.0}).at(0).state),
            "oak_trapdoor[facing=north,half=bottom,open=true,powered=false,waterlogged=false]");
  EXPECT_TRUE(useOf(world, {0, 63, 0}, {0.0, 0.0, 1.0}).empty()) << "stone does not open";
  // Picking gives the block's default state, a torch for a wall torch.
  EXPECT_EQ(pickedBy(world, {0, 65, 0}), b.id("oak_door"));
  world.setBlock({7, 64, 0}, b.id("wall_torch[facing=west]"));
  EXPECT_EQ(pickedBy(world, {7, 64, 0}), b.id("torch"));
  EXPECT_EQ(brokenBy(world, {0, 63, 0}).size(), 1u);
}

// A shaped block is hit where the ray meets its boxes: a ray over a bottom slab's open half goes on
// to what lies behind, one onto its top hits it there, and the outline is the slab's, not the cell's.
TEST(TargetingTest, ShapedBlocksAreHitByTheirBoxesAndOutlinedByThem) {
  World world = flatWorld();
  world.setShapes(&defaultShapes());
  world.setBlock({0, 64, 2}, defaultBlocks().id("stone_slab"));
  world.setBlock({0, 64, 4}, defaultBlocks().id("stone"));
  const auto over = targetBlock(world, {0.5, 64.75, 0.5}, {0.0, 0.0, 1.0});
  ASSERT_TRUE(over);
  EXPECT_EQ(over->block, (BlockPos{0, 64, 4})) << "over the slab's open upper half";
  const auto onto = targetBlock(world, {0.5, 64.25, 0.5}, {0.0, 0.0, 1.0});
  ASSERT_TRUE(onto);
  EXPECT_EQ(onto->block, (BlockPos{0, 64, 2}));
  EXPECT_EQ(onto->normal, glm::ivec3(0, 0, -1));
  EXPECT_NEAR(onto->distance, 1.5, 1e-9);
  const auto down = targetBlock(world, {0.5, 66.0, 2.5}, {0.0, -1.0, 0.0});
  ASSERT_TRUE(down);
  EXPECT_EQ(down->block, (BlockPos{0, 64, 2}));
  EXPECT_EQ(down->normal, glm::ivec3(0, 1, 0));
  EXPECT_NEAR(down->distance, 1.5, 1e-9) << "its top is at 64.5";
  const WorldBox outline = outlineOf(world, {0, 64, 2});
  EXPECT_EQ(outline.min, glm::dvec3(0.0, 64.0, 2.0));
  EXPECT_EQ(outline.max, glm::dvec3(1.0, 64.5, 3.0));
  EXPECT_EQ(outlineOf(world, {0, 64, 4}).max, glm::dvec3(1.0, 65.0, 5.0));
}

// A block that can stand in water placed in water keeps it, and leaves it when broken; one that
// cannot (stone), and a slab joined into a double slab, do not.
TEST(PlacementTest, BlocksPlacedInWaterKeepTheWater) {
  World world = flatWorld();
  world.setShapes(&defaultShapes());
  const BlockRegistry& b = defaultBlocks();
  const glm::dvec3 south(0.0, -0.5, 1.0);
  const Target floor{{0, 63, 0}, {0, 1, 0}, {0, 64, 0}, 1.0};
  world.setBlock({0, 64, 0}, b.id("water"));
  const auto placed = [&](const char* block) {
    const std::vector<Placement> cells =
        placementOf(world, b.id(block), floor, floor.place, {0.5, 64.0, 0.5}, south);
    return cells.size() == 1 ? b.stateName(cells[0].state) : std::string("?");
  };
  EXPECT_EQ(placed("oak_stairs"), "oak_stairs[facing=south,half=bottom,shape=straight,waterlogged=true]");
  EXPECT_EQ(placed("glass_pane"),
            "glass_pane[east=false,north=false,south=false,waterlogged=true,west=false]");
  EXPECT_EQ(placed("lantern"), "lantern[hanging=false,waterlogged=true]");
  EXPECT_EQ(placed("stone"), "stone");
  world.setBlock({0, 64, 0}, b.id("stone_slab[type=bottom,waterlogged=true]"));
  const Target onSlab{{0, 64, 0}, {0, 1, 0}, {0, 65, 0}, 1.0};
  const auto joined = placementOf(world, b.id("stone_slab"), onSlab, onSlab.place, {0.5, 64.5, 0.5}, south);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(b.stateName(joined[0].state), "stone_slab[type=double,waterlogged=false]");
  // Broken, a waterlogged block leaves its water; a dry one air.
  const std::vector<Placement> broken = brokenBy(world, {0, 64, 0});
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken[0].state, b.waterState());
  EXPECT_EQ(brokenBy(world, {0, 63, 0})[0].state, kAir);
}

}  // namespace
}  // namespace terrasol
