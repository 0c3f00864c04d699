#pragma once
// States that follow their neighbours, as Minecraft's do: stairs become inner and outer corners
// against stairs beside them (StairBlock.getStairsShape). A block is a stair here by its properties:
// "facing", "half" and a "shape" with straight, inner_left, inner_right, outer_left and outer_right.

#include <utility>
#include <vector>

#include "world/world.h"

namespace terrasol {

// `state` at `pos` as its neighbours in `world` make it (itself when nothing connects).
BlockId connectedState(const World& world, const BlockPos& pos, BlockId state);

// After the block at `changed` changed: the cells (it and its four horizontal neighbours) whose
// connected state is now different, with that state, for the caller to set.
std::vector<std::pair<BlockPos, BlockId>> connectionUpdates(const World& world, const BlockPos& changed);

}  // namespace terrasol
