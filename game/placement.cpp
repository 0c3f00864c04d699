#include "placement.h"

#include <cmath>

namespace terrasol {
namespace {

// The horizontal direction the player looks most along, as Minecraft names facings.
const char* facingOf(glm::dvec3 look) {
  if (std::abs(look.x) > std::abs(look.z)) return look.x > 0.0 ? "east" : "west";
  return look.z > 0.0 ? "south" : "north";
}

}  // namespace

Placement placementOf(const World& world, BlockId held, const Target& target, BlockPos at, glm::dvec3 hit,
                      glm::dvec3 look) {
  const BlockRegistry& blocks = world.blocks();
  // A slab clicked on its open side becomes a double slab where it is.
  const BlockId there = world.getBlock(target.block);
  if (&blocks[there] == &blocks[held]) {
    const StateValues values = blocks.stateValues(there);
    const auto type = values.find("type");
    if (type != values.end() && ((type->second == "bottom" && target.normal.y == 1) ||
                                 (type->second == "top" && target.normal.y == -1))) {
      if (const auto full = blocks.with(there, "type", "double")) return {target.block, *full};
    }
  }
  // The upper half: against a ceiling, or clicked above a side's middle.
  const bool upper = target.normal.y == -1 || (target.normal.y == 0 && hit.y - std::floor(hit.y) > 0.5);
  BlockId state = held;
  for (const char* property : {"half", "type"}) {  // stairs' half, slabs' type
    if (const auto s = blocks.with(state, property, upper ? "top" : "bottom")) state = *s;
  }
  if (const auto s = blocks.with(state, "facing", facingOf(look))) state = *s;
  return {at, state};
}

}  // namespace terrasol
