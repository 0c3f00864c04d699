#include "placement.h"

#include <cmath>
#include <optional>
#include <string>

namespace terrasol {
namespace {

// The horizontal direction the player looks most along, as Minecraft names facings.
std::string facingOf(glm::dvec3 look) {
  if (std::abs(look.x) > std::abs(look.z)) return look.x > 0.0 ? "east" : "west";
  return look.z > 0.0 ? "south" : "north";
}

std::string opposite(const std::string& f) {
  return f == "north" ? "south" : f == "south" ? "north" : f == "west" ? "east" : "west";
}

// Seen from above, a quarter turn anticlockwise (Minecraft's getCounterClockWise) and clockwise.
std::string counterClockwise(const std::string& f) {
  return f == "north" ? "west" : f == "west" ? "south" : f == "south" ? "east" : "north";
}
std::string clockwise(const std::string& f) {
  return opposite(counterClockwise(f));
}

BlockPos step(const BlockPos& p, const std::string& f) {
  return f == "north"   ? p.offset(0, 0, -1)
         : f == "south" ? p.offset(0, 0, 1)
         : f == "west"  ? p.offset(-1, 0, 0)
                        : p.offset(1, 0, 0);
}

// The facing a clicked side's normal points along; "" for the top or bottom.
std::string sideOf(glm::ivec3 normal) {
  if (normal.x != 0) return normal.x > 0 ? "east" : "west";
  if (normal.z != 0) return normal.z > 0 ? "south" : "north";
  return "";
}

// `state` with each of the property values set, where its block has them.
BlockId with(const BlockRegistry& blocks, BlockId state,
             std::initializer_list<std::pair<const char*, std::string>> values) {
  for (const auto& [property, value] : values) state = blocks.with(state, property, value).value_or(state);
  return state;
}

std::string valueOf(const BlockRegistry& blocks, BlockId state, const char* property) {
  const StateValues v = blocks.stateValues(state);
  const auto it = v.find(property);
  return it == v.end() ? "" : it->second;
}

// Minecraft's rotation toward the player: sixteenths of a turn from south, clockwise seen from above,
// of the way back along the look.
int rotationToward(glm::dvec3 look) {
  const double yaw = std::atan2(-look.x, look.z) * 180.0 / 3.14159265358979323846;  // 0 = looking south
  return static_cast<int>(std::floor((yaw + 180.0) * 16.0 / 360.0 + 0.5)) & 15;
}

// Whether the block at `pos` fills its cell (a cube, a double slab): what walls and door hinges lean on.
bool wholeBlock(const World& world, const BlockPos& pos) {
  const BlockId s = world.getBlock(pos);
  return world.opaqueCubes()[s] || (world.shapes() && world.shapes()->wholeCell(s));
}

// Minecraft's DoorBlock.getHinge: the side with more whole blocks beside it, the side away from a
// door it would pair with, else the side of the cell the click was on.
std::string hingeOf(const World& world, BlockId door, const BlockPos& at, const std::string& facing,
                    glm::dvec3 hit) {
  const BlockRegistry& blocks = world.blocks();
  const BlockPos left = step(at, counterClockwise(facing)), right = step(at, clockwise(facing));
  const int i = -wholeBlock(world, left) - wholeBlock(world, left.offset(0, 1, 0)) +
                wholeBlock(world, right) + wholeBlock(world, right.offset(0, 1, 0));
  const auto lowerDoor = [&](const BlockPos& p) {
    const BlockId s = world.getBlock(p);
    return &blocks[s] == &blocks[door] && valueOf(blocks, s, "half") == "lower";
  };
  const bool doorLeft = lowerDoor(left), doorRight = lowerDoor(right);
  if ((doorLeft && !doorRight) || i > 0) return "right";
  if ((doorRight && !doorLeft) || i < 0) return "left";
  const double x = hit.x - at.x, z = hit.z - at.z;
  const BlockPos& o = step(BlockPos{0, 0, 0}, facing);
  const bool leftHalf =
      (o.x >= 0 || z >= 0.5) && (o.x <= 0 || z <= 0.5) && (o.z >= 0 || x <= 0.5) && (o.z <= 0 || x >= 0.5);
  return leftHalf ? "left" : "right";
}

// Whether the cell holds water: a water block, or a block standing in water.
bool holdsWater(const World& world, const BlockPos& pos) {
  const BlockRegistry& blocks = world.blocks();
  const BlockId state = world.getBlock(pos);
  return blocks.holdsWater()[state] != 0 ||
         (blocks.waterState() != kAir && &blocks[state] == &blocks[blocks.waterState()]);
}

// The cells and states by the held block's rule, before water is kept.
std::vector<Placement> placedStates(const World& world, BlockId held, const Target& target, BlockPos at,
                                    glm::dvec3 hit, glm::dvec3 look) {
  const BlockRegistry& blocks = world.blocks();
  const BlockType& type = blocks[held];
  const BlockId there = world.getBlock(target.block);
  const bool same = &blocks[there] == &type;
  // The upper half: against a ceiling, or clicked above a side's middle.
  const bool upper = target.normal.y == -1 || (target.normal.y == 0 && hit.y - std::floor(hit.y) > 0.5);
  const PlacementRule rule = type.placement;
  const std::string side = sideOf(target.normal);
  switch (rule) {
    case PlacementRule::Slab: {
      // A slab clicked on its open side becomes a double slab where it is.
      const std::string half = valueOf(blocks, there, "type");
      if (same && ((half == "bottom" && target.normal.y == 1) || (half == "top" && target.normal.y == -1))) {
        return {{target.block, with(blocks, there, {{"type", "double"}})}};
      }
      return {{at, with(blocks, held, {{"type", upper ? "top" : "bottom"}})}};
    }
    case PlacementRule::Layers:
      if (const std::string n = valueOf(blocks, there, "layers"); same && target.normal.y == 1 && n != "8") {
        return {{target.block, with(blocks, there, {{"layers", std::to_string(std::stoi(n) + 1)}})}};
      }
      return {{at, held}};
    case PlacementRule::Stairs:
      return {{at, with(blocks, held, {{"half", upper ? "top" : "bottom"}, {"facing", facingOf(look)}})}};
    case PlacementRule::Axis: {
      const char* axis = target.normal.x != 0 ? "x" : target.normal.z != 0 ? "z" : "y";
      return {{at, with(blocks, held, {{"axis", axis}})}};
    }
    case PlacementRule::Facing:
      return {{at, with(blocks, held, {{"facing", facingOf(look)}})}};
    case PlacementRule::FacingBack:
      return {{at, with(blocks, held, {{"facing", opposite(facingOf(look))}})}};
    case PlacementRule::Trapdoor:
      // On a side it hangs from that side, at the half clicked; on a top or bottom it faces the player.
      if (!side.empty())
        return {{at, with(blocks, held, {{"facing", side}, {"half", upper ? "top" : "bottom"}})}};
      return {{at, with(blocks, held,
                        {{"facing", opposite(facingOf(look))}, {"half", upper ? "top" : "bottom"}})}};
    case PlacementRule::Wall:
    case PlacementRule::Torch:
      // Against a wall's whole side; a torch stands on a floor too.
      if (!side.empty() && wholeBlock(world, target.block)) {
        const BlockId wall = rule == PlacementRule::Torch ? type.wallVariant : held;
        return {{at, with(blocks, wall, {{"facing", side}})}};
      }
      if (rule == PlacementRule::Torch && target.normal.y == 1) return {{at, held}};
      return {};
    case PlacementRule::Door: {
      const std::string facing = facingOf(look);
      const BlockId lower = with(blocks, held,
                                 {{"facing", facing},
                                  {"half", "lower"},
                                  {"hinge", hingeOf(world, held, at, facing, hit)},
                                  {"open", "false"}});
      return {{at, lower}, {at.offset(0, 1, 0), with(blocks, lower, {{"half", "upper"}})}};
    }
    case PlacementRule::Pointing: {
      // Out of the clicked face; a hopper (no "up") points into the block it was put against.
      if (!blocks.with(held, "facing", "up"))
        return {{at, with(blocks, held, {{"facing", side.empty() ? "down" : opposite(side)}})}};
      return {{at, with(blocks, held,
                        {{"facing", side.empty() ? (target.normal.y > 0 ? "up" : "down") : side}})}};
    }
    case PlacementRule::Attached:
      // On a wall facing out of it; on a floor or ceiling facing the way the player looks.
      if (!side.empty()) return {{at, with(blocks, held, {{"face", "wall"}, {"facing", side}})}};
      return {{at, with(blocks, held,
                        {{"face", target.normal.y > 0 ? "floor" : "ceiling"}, {"facing", facingOf(look)}})}};
    case PlacementRule::Rotation:
      // On a side, the wall form facing out of it; else turned to face the player in sixteenths.
      if (!side.empty() && type.wallVariant != kAir)
        return {{at, with(blocks, type.wallVariant, {{"facing", side}})}};
      return {{at, with(blocks, held, {{"rotation", std::to_string(rotationToward(look))}})}};
    case PlacementRule::TwoTall: {
      const BlockId lower = with(blocks, held, {{"half", "lower"}, {"facing", opposite(facingOf(look))}});
      return {{at, lower}, {at.offset(0, 1, 0), with(blocks, lower, {{"half", "upper"}})}};
    }
    case PlacementRule::Bed: {
      // The foot where it is put, the head a cell further along the player's look.
      const std::string facing = facingOf(look);
      const BlockId foot = with(blocks, held, {{"facing", facing}, {"part", "foot"}});
      return {{at, foot}, {step(at, facing), with(blocks, foot, {{"part", "head"}})}};
    }
    case PlacementRule::Rail: {
      if (!wholeBlock(world, at.offset(0, -1, 0))) return {};
      const std::string f = facingOf(look);
      return {
          {at, with(blocks, held, {{"shape", f == "north" || f == "south" ? "north_south" : "east_west"}})}};
    }
    case PlacementRule::None:
      break;
  }
  return {{at, held}};
}

}  // namespace

std::vector<Placement> placementOf(const World& world, BlockId held, const Target& target, BlockPos at,
                                   glm::dvec3 hit, glm::dvec3 look) {
  std::vector<Placement> cells = placedStates(world, held, target, at, hit, look);
  // A block that can stand in water keeps the water of the cell it goes in; a double slab cannot.
  for (Placement& cell : cells) {
    const bool water = holdsWater(world, cell.at) && valueOf(world.blocks(), cell.state, "type") != "double";
    cell.state =
        world.blocks().with(cell.state, "waterlogged", water ? "true" : "false").value_or(cell.state);
  }
  return cells;
}

std::vector<Placement> useOf(const World& world, const BlockPos& pos, glm::dvec3 look) {
  const BlockRegistry& blocks = world.blocks();
  const BlockId state = world.getBlock(pos);
  const BlockType& type = blocks[state];
  if (!type.opens) return {};
  const bool open = valueOf(blocks, state, "open") != "true";
  BlockId toggled = with(blocks, state, {{"open", open ? "true" : "false"}});
  // A gate opened from its far side turns to swing away from the player, as Minecraft's does.
  if (open && type.placement == PlacementRule::Facing &&
      valueOf(blocks, state, "facing") == opposite(facingOf(look))) {
    toggled = with(blocks, toggled, {{"facing", facingOf(look)}});
  }
  std::vector<Placement> cells = {{pos, toggled}};
  if (type.placement == PlacementRule::Door) {
    const BlockPos other = pos.offset(0, valueOf(blocks, state, "half") == "lower" ? 1 : -1, 0);
    const BlockId o = world.getBlock(other);
    if (&blocks[o] == &type) cells.push_back({other, with(blocks, o, {{"open", open ? "true" : "false"}})});
  }
  return cells;
}

BlockId pickedBy(const World& world, const BlockPos& pos) {
  const BlockRegistry& blocks = world.blocks();
  const BlockType& type = blocks[world.getBlock(pos)];
  for (std::size_t i = 0; i < blocks.blockCount(); ++i) {
    const BlockId wall = blocks.block(i).wallVariant;
    if (wall != kAir && &blocks[wall] == &type) return blocks.block(i).defaultState;
  }
  return type.defaultState;
}

std::vector<Placement> brokenBy(const World& world, const BlockPos& pos) {
  const BlockRegistry& blocks = world.blocks();
  const BlockId state = world.getBlock(pos);
  // A block standing in water leaves the water.
  const auto left = [&](const BlockPos& p) {
    return Placement{p, blocks.holdsWater()[world.getBlock(p)] != 0 ? blocks.waterState() : kAir};
  };
  std::vector<Placement> cells = {left(pos)};
  // A block of two cells goes whole: a door's or tall plant's other half, a bed's other part.
  const PlacementRule rule = blocks[state].placement;
  std::optional<BlockPos> other;
  if (rule == PlacementRule::Door || rule == PlacementRule::TwoTall)
    other = pos.offset(0, valueOf(blocks, state, "half") == "lower" ? 1 : -1, 0);
  if (rule == PlacementRule::Bed) {
    const std::string facing = valueOf(blocks, state, "facing");
    other = step(pos, valueOf(blocks, state, "part") == "foot" ? facing : opposite(facing));
  }
  if (other && &blocks[world.getBlock(*other)] == &blocks[state]) cells.push_back(left(*other));
  return cells;
}

}  // namespace terrasol
