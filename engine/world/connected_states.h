#pragma once
// States that follow their neighbours, as Minecraft's do: stairs become inner and outer corners
// against stairs beside them (StairBlock.getStairsShape). A block is a stair here by its properties:
// "facing", "half" and a "shape" with straight, inner_left, inner_right, outer_left and outer_right.
// Fences, panes and walls (blocks.json's "connects") join the sides where a neighbour of their kind,
// a fence gate across their line or a whole face (a cube's side, a double slab) is: fences join
// fences, panes and walls each other; a wall's side is tall under a block whose bottom is whole, and
// its post shows unless it runs straight.

#include <utility>
#include <vector>

#include "world/world.h"

namespace terrasol {

// `state` at `pos` as its neighbours in `world` make it (itself when nothing connects).
BlockId connectedState(const World& world, const BlockPos& pos, BlockId state);

// After the block at `changed` changed: the cells (it, its four horizontal neighbours and the one
// below) whose connected state is now different, with that state, for the caller to set.
std::vector<std::pair<BlockPos, BlockId>> connectionUpdates(const World& world, const BlockPos& changed);

}  // namespace terrasol
