#pragma once
// Minecraft's rules for what placing, using and breaking a block changes, by each block's placement
// rule (blocks.json's "placement"): stairs face the way the player looks and turn upside down against
// a ceiling or on a side's upper half; slabs go to the top or bottom half by the same rule and a slab
// clicked on its open side becomes a double slab; snow layers pile up; logs lie along the clicked
// face's axis; gates face the way the player looks and furnaces face the player; doors take two
// cells, their hinge on the side their neighbours or the click decide; trapdoors hang from the
// clicked side's upper or lower half; ladders and wall torches go on a wall's side, a torch on a side
// becomes a wall torch. Minecraft's blocks that blocks.json gives no rule follow the one their
// properties imply (world/block_registry.h): six facings point out of the clicked face, buttons and
// levers go on a floor, wall or ceiling, signs, banners and heads turn to face the player or hang on a
// wall as their wall form, tall plants take two cells up and beds two along the look, rails lie on a
// whole block's top. A block that can stand in water placed in water keeps it (waterlogged), and
// leaves it when broken, a two-cell block whole. Using a block that opens toggles it (a door's two
// halves together).

#include <glm/vec3.hpp>
#include <vector>

#include "targeting.h"
#include "world/world.h"

namespace terrasol {

struct Placement {
  BlockPos at;
  BlockId state;
};

// The cells a held block fills, with their states; none where it cannot go (a ladder on a floor).
// `at`: the cell it goes in (the target's `place`, or the target itself where it is replaceable);
// `hit`: where the crosshair's ray meets the target; `look`: the player's view direction. A cell that
// is the target itself joins what is there (a double slab, another snow layer); the others must be
// free, which the caller checks.
std::vector<Placement> placementOf(const World& world, BlockId held, const Target& target, BlockPos at,
                                   glm::dvec3 hit, glm::dvec3 look);

// Using the block at `pos` (a right click): the cells a block that opens changes, none for others.
std::vector<Placement> useOf(const World& world, const BlockPos& pos, glm::dvec3 look);

// What picking the block at `pos` (a middle click) puts in the hand: its block's default state, a
// torch for a wall torch.
BlockId pickedBy(const World& world, const BlockPos& pos);

// The cells breaking the block at `pos` changes, and what is left in them: it, and a door's other
// half; air, or the water a block stood in.
std::vector<Placement> brokenBy(const World& world, const BlockPos& pos);

}  // namespace terrasol
