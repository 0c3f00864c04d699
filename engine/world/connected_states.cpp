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

// Whether `state`'s side `side` is whole: an opaque cube's, or one its shape's boxes cover. Leaves
// are left out, as Minecraft leaves them out of connections.
bool wholeSide(const World& world, BlockId state, Direction side) {
  if (world.opaqueCubes()[state]) return true;
  if (world.blocks()[state].tint == Tint::Foliage) return false;
  return world.shapes() && FaceCoverage::of(world.shapes()->boxes(state)).full(side);
}

// Whether a fence, pane or wall of kind `kind` joins the neighbour `n` on its side `side`: fences join
// fences, panes and walls each other, fences and walls gates; anything joins a whole side.
bool joins(const World& world, Connects kind, BlockId n, Direction side) {
  switch (world.blocks()[n].connects) {
    case Connects::Fence:
      if (kind == Connects::Fence) return true;
      break;
    case Connects::Pane:
    case Connects::Wall:
      if (kind != Connects::Fence) return true;
      break;
    case Connects::Gate:
      if (kind != Connects::Pane) {
        // A gate joins along its bars: facing north or south, it runs east-west.
        const StateValues v = world.blocks().stateValues(n);
        const auto facing = v.find("facing");
        const bool northSouth = facing != v.end() && (facing->second == "north" || facing->second == "south");
        return northSouth == (side == Direction::East || side == Direction::West);
      }
      break;
    case Connects::None:
      break;
  }
  return wholeSide(world, n, opposite(side));
}

BlockId connectedSides(const World& world, const BlockPos& pos, BlockId state, Connects kind) {
  const BlockRegistry& blocks = world.blocks();
  static constexpr std::array<std::pair<Direction, const char*>, 4> kSides = {{{Direction::North, "north"},
                                                                               {Direction::East, "east"},
                                                                               {Direction::South, "south"},
                                                                               {Direction::West, "west"}}};
  const BlockId above = world.getBlock(pos.offset(0, 1, 0));
  const bool tall = wholeSide(world, above, Direction::Down);
  bool joined[4];
  for (std::size_t k = 0; k < kSides.size(); ++k) {
    const auto [side, name] = kSides[k];
    joined[k] = joins(world, kind, world.neighbour(pos, side), side);
    const char* value = kind != Connects::Wall ? (joined[k] ? "true" : "false")
                        : !joined[k]           ? "none"
                        : tall                 ? "tall"
                                               : "low";
    state = blocks.with(state, name, value).value_or(state);
  }
  if (kind == Connects::Wall) {
    // The post shows unless the wall runs straight through (two opposite sides and nothing else), or
    // where a wall's post stands on it.
    const bool straight = (joined[0] && joined[2] && !joined[1] && !joined[3]) ||
                          (joined[1] && joined[3] && !joined[0] && !joined[2]);
    const bool postAbove =
        blocks[above].connects == Connects::Wall && blocks.stateValues(above).at("up") == "true";
    state = blocks.with(state, "up", straight && !postAbove ? "false" : "true").value_or(state);
  }
  return state;
}

}  // namespace

BlockId connectedState(const World& world, const BlockPos& pos, BlockId state) {
  const BlockType& type = world.blocks()[state];
  if (type.properties.empty()) return state;  // most cells: nothing to look up
  switch (type.connects) {
    case Connects::Fence:
    case Connects::Pane:
    case Connects::Wall:
      return connectedSides(world, pos, state, type.connects);
    case Connects::Gate:
    case Connects::None:
      break;  // stairs, below
  }
  const auto self = stairOf(world.blocks(), state);
  if (!self) return state;
  return world.blocks().with(state, "shape", stairShape(world, pos, *self)).value_or(state);
}

std::vector<std::pair<BlockPos, BlockId>> connectionUpdates(const World& world, const BlockPos& changed) {
  std::vector<std::pair<BlockPos, BlockId>> updates;
  const std::array<BlockPos, 6> cells = {changed,
                                         changed.offset(-1, 0, 0),
                                         changed.offset(1, 0, 0),
                                         changed.offset(0, 0, -1),
                                         changed.offset(0, 0, 1),
                                         changed.offset(0, -1, 0)};
  for (const BlockPos& p : cells) {
    const BlockId now = world.getBlock(p);
    const BlockId connected = connectedState(world, p, now);
    if (connected != now) updates.emplace_back(p, connected);
  }
  return updates;
}

}  // namespace terrasol
