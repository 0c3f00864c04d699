#include "world/connected_states.h"

#include <array>
#include <optional>
#include <string>

namespace terrasol {
namespace {

struct Stair {
  std::string facing, half;
};

// The state's stair properties, or nothing when it is not a stair.
std::optional<Stair> stairOf(const BlockRegistry& blocks, BlockId state) {
  const StateValues v = blocks.stateValues(state);
  const auto facing = v.find("facing"), half = v.find("half"), shape = v.find("shape");
  if (facing == v.end() || half == v.end() || shape == v.end()) return std::nullopt;
  if (!blocks.with(state, "shape", "inner_left")) return std::nullopt;
  return Stair{facing->second, half->second};
}

BlockPos step(const BlockPos& p, const std::string& facing) {
  if (facing == "north") return p.offset(0, 0, -1);
  if (facing == "south") return p.offset(0, 0, 1);
  if (facing == "west") return p.offset(-1, 0, 0);
  return p.offset(1, 0, 0);
}

std::string opposite(const std::string& f) {
  return f == "north" ? "south" : f == "south" ? "north" : f == "west" ? "east" : "west";
}

// Seen from above, a quarter turn anticlockwise: north to west, west to south, south to east.
std::string counterClockwise(const std::string& f) {
  return f == "north" ? "west" : f == "west" ? "south" : f == "south" ? "east" : "north";
}

bool sameAxis(const std::string& a, const std::string& b) {
  return a == b || a == opposite(b);
}

// Whether the neighbour on side `face` lets the stair take a corner: it is not a stair facing and
// sitting as this one does.
bool canTakeShape(const World& world, const BlockPos& pos, const Stair& self, const std::string& face) {
  const auto n = stairOf(world.blocks(), world.getBlock(step(pos, face)));
  return !n || n->facing != self.facing || n->half != self.half;
}

const char* stairShape(const World& world, const BlockPos& pos, const Stair& self) {
  if (const auto front = stairOf(world.blocks(), world.getBlock(step(pos, self.facing)));
      front && front->half == self.half && !sameAxis(front->facing, self.facing) &&
      canTakeShape(world, pos, self, opposite(front->facing))) {
    return front->facing == counterClockwise(self.facing) ? "outer_left" : "outer_right";
  }
  if (const auto back = stairOf(world.blocks(), world.getBlock(step(pos, opposite(self.facing))));
      back && back->half == self.half && !sameAxis(back->facing, self.facing) &&
      canTakeShape(world, pos, self, back->facing)) {
    return back->facing == counterClockwise(self.facing) ? "inner_left" : "inner_right";
  }
  return "straight";
}

}  // namespace

BlockId connectedState(const World& world, const BlockPos& pos, BlockId state) {
  if (world.blocks()[state].properties.empty()) return state;  // most cells: nothing to look up
  const auto self = stairOf(world.blocks(), state);
  if (!self) return state;
  return world.blocks().with(state, "shape", stairShape(world, pos, *self)).value_or(state);
}

std::vector<std::pair<BlockPos, BlockId>> connectionUpdates(const World& world, const BlockPos& changed) {
  std::vector<std::pair<BlockPos, BlockId>> updates;
  const std::array<BlockPos, 5> cells = {changed, changed.offset(-1, 0, 0), changed.offset(1, 0, 0),
                                         changed.offset(0, 0, -1), changed.offset(0, 0, 1)};
  for (const BlockPos& p : cells) {
    const BlockId now = world.getBlock(p);
    const BlockId connected = connectedState(world, p, now);
    if (connected != now) updates.emplace_back(p, connected);
  }
  return updates;
}

}  // namespace terrasol
