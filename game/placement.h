#pragma once
// Minecraft's placement rules for the state a held block takes where it is placed: stairs face the
// way the player looks and turn upside down against a ceiling or on a side's upper half; slabs go to
// the top or bottom of the cell by the same rule, and a slab clicked on its open side joins it into
// a double slab. Blocks without those properties keep the held state.

#include <glm/vec3.hpp>
#include <optional>

#include "targeting.h"
#include "world/world.h"

namespace terrasol {

struct Placement {
  BlockPos at;
  BlockId state;
};

// `at`: the cell the block goes in (the target's `place`, or the target itself where it is
// replaceable); `hit`: where the crosshair's ray meets the target; `look`: the player's view direction.
Placement placementOf(const World& world, BlockId held, const Target& target, BlockPos at, glm::dvec3 hit,
                      glm::dvec3 look);

}  // namespace terrasol
