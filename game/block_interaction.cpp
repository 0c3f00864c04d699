#include "block_interaction.h"

#include <utility>

#include "core/error.h"
#include "core/log.h"
#include "placement.h"
#include "world/liquid.h"

namespace terrasol {
namespace {

constexpr double kBreakRepeat = 0.25, kPlaceRepeat = 0.2;  // Minecraft's creative delays (5 and 4 ticks)

// Pressed now, or held once its repeat delay has run out.
bool fires(const FrameInput& in, MouseButton button, double cooldown) {
  return in.wasPressed(button) || (in.isHeld(button) && cooldown <= 0.0);
}

}  // namespace

void BlockInteraction::update(const FrameInput& in, double dt, PlayWorld& world) {
  breakCooldown_ -= dt;
  placeCooldown_ -= dt;
  const Player& player = world.player();
  target_ = targetBlock(world.world(), player.eye(), player.forward());
  // A prop in front of the targeted block (or in the open) is what the crosshair is on: breaking
  // removes it, and no block is used through it.
  const auto prop = world.props().placed().pick(player.eye(), player.forward(), kReach);
  targetProp_.reset();
  // A prop standing in a plant's cell is entered where the cell is: the prop wins the tie.
  if (prop && (!target_ || prop->distance <= target_->distance + 1e-9)) targetProp_ = prop->index;
  if (targetProp_) return useTargetedProp(in, world);
  if (!target_) return;
  if (in.wasPressed(MouseButton::Middle)) hotbar_.pick(pickedBy(world.world(), target_->block));
  if (survival_) {
    clicked_ |= in.wasPressed(MouseButton::Left);
    if (digging_.block()) return;  // nothing is used or placed while a block is dug, as in Minecraft
  } else if (fires(in, MouseButton::Left, breakCooldown_)) {
    breakTarget(world);
    breakCooldown_ = kBreakRepeat;
    return;
  }
  if (!fires(in, MouseButton::Right, placeCooldown_)) return;
  placeCooldown_ = kPlaceRepeat;
  // A block that opens is opened or closed instead.
  if (const auto used = useOf(world.world(), target_->block, player.forward()); !used.empty()) {
    for (const Placement& cell : used) world.editBlock(cell.at, cell.state);
    return;
  }
  placeHeld(world);
}

std::optional<DigHit> BlockInteraction::digTick(bool held, PlayWorld& world) {
  if (!survival_) return std::nullopt;
  const Player& player = world.player();
  DigInput in;
  in.clicked = std::exchange(clicked_, false);
  in.held = held;
  if (target_ && !targetProp_) in.target = target_->block;
  const BlockId state = in.target ? world.world().getBlock(*in.target) : kAir;
  in.hardness = content_.blocks[state].hardness;
  in.hampered = !player.onGround() || underWater(world.world(), player.eye());
  const Digging::Tick tick = digging_.tick(in);
  if (tick.broken) breakTarget(world);
  if (!tick.hit) return std::nullopt;
  return DigHit{*in.target, state};
}

std::optional<BlockCrack> BlockInteraction::crack() const {
  const std::optional<int> stage = digging_.crackStage();
  if (!stage) return std::nullopt;
  const BlockPos at = *digging_.block();
  const glm::dvec3 corner(at.x, at.y, at.z);
  return BlockCrack{{corner, corner + glm::dvec3(1.0)}, *stage};
}

void BlockInteraction::breakTarget(PlayWorld& world) {
  for (const Placement& cell : brokenBy(world.world(), target_->block)) world.editBlock(cell.at, cell.state);
  const Player& player = world.player();
  target_ = targetBlock(world.world(), player.eye(), player.forward());
}

void BlockInteraction::useTargetedProp(const FrameInput& in, PlayWorld& world) {
  if (!fires(in, MouseButton::Left, breakCooldown_)) return;
  logInfo("removed the prop " + world.props().prop(*targetProp_).model);
  world.removeProp(*targetProp_);
  targetProp_.reset();
  breakCooldown_ = kBreakRepeat;
}

void BlockInteraction::placeHeld(PlayWorld& world) {
  const World& w = world.world();
  const Player& player = world.player();
  // A plant under the crosshair is replaced, as in Minecraft; anything else gets the block beside it.
  const BlockPos at = replaceable(w, target_->block) ? target_->block : target_->place;
  const glm::dvec3 hit = player.eye() + player.forward() * target_->distance;
  const std::vector<Placement> cells = placementOf(w, hotbar_.held(), *target_, at, hit, player.forward());
  for (const Placement& cell : cells) {
    if (cell.at == target_->block && !replaceable(w, cell.at)) continue;  // joins it
    if (!inWorldHeight(cell.at.y) || !replaceable(w, cell.at)) return;
    if (blocksPlayer(player, cell.at, cell.state)) return;  // never inside the player
    const BlockType& type = content_.blocks[cell.state];
    if ((type.shape == BlockShape::Cross || type.shape == BlockShape::Torch) &&
        !w.opaqueCubes()[w.getBlock(cell.at.offset(0, -1, 0))]) {
      return;  // torches and plants stand on a full block
    }
  }
  for (const Placement& cell : cells) world.editBlock(cell.at, cell.state);
}

void BlockInteraction::placeProp(const std::string& model, PlayWorld& world) {
  if (model.empty()) {
    logWarning("no prop to place: put .gltf or .glb files in " + (world.streamed().dir() / "props").string() +
               " and choose one in the menu's Props tab");
    return;
  }
  const World& w = world.world();
  // As for blocks: a plant under the crosshair gives its own cell, anything else the cell beside it.
  std::optional<BlockPos> at;
  if (target_) at = replaceable(w, target_->block) ? target_->block : target_->place;
  if (!at || !inWorldHeight(at->y) || !replaceable(w, *at)) {
    logWarning("no prop placed: look at a block with room beside it");
    return;
  }
  try {
    const LevelProp prop = world.props().standingIn(model, *at);
    const WorldBounds box = world.props().boundsOf(prop);
    const Box body = world.player().box();
    if (body.min.x < box.max.x && body.max.x > box.min.x && body.min.y < box.max.y &&
        body.max.y > box.min.y && body.min.z < box.max.z && body.max.z > box.min.z) {
      logWarning("no prop placed: it would stand in the player");
      return;
    }
    // The prop takes a plant's place, as a block would.
    if (w.getBlock(*at) != kAir) world.editBlock(*at, kAir);
    world.placeProp(prop);
    logInfo("placed " + model);
  } catch (const Error& e) {
    logError(std::string("prop not placed: ") + e.what());
  }
}

std::optional<WorldBox> BlockInteraction::outline(const PlayWorld& world) const {
  if (targetProp_) {
    const WorldBounds b = world.props().placed().bounds(*targetProp_);
    return WorldBox{b.min, b.max};
  }
  if (target_) return outlineOf(world.world(), target_->block);
  return std::nullopt;
}

bool BlockInteraction::replaceable(const World& world, const BlockPos& at) const {
  const BlockShape shape = content_.blocks[world.getBlock(at)].shape;
  return shape == BlockShape::None || shape == BlockShape::Liquid || shape == BlockShape::Cross;
}

bool BlockInteraction::blocksPlayer(const Player& player, const BlockPos& at, BlockId state) const {
  const Box body = player.box();
  for (const Box& b : collisionBoxes(content_.shapes, state, at)) {
    if (overlaps(b, body)) return true;
  }
  return false;
}

}  // namespace terrasol
