#include <algorithm>

#include "core/error.h"
#include "core/log.h"
#include "game_props.h"
#include "game_renderer.h"
#include "game_session.h"
#include "pipeline/streamed_world.h"
#include "placement.h"
#include "targeting.h"
#include "world/connected_states.h"

// Changing the world: breaking, placing and picking blocks, and placing props.

namespace terrasol::session {
namespace {

constexpr double kBreakRepeat = 0.25, kPlaceRepeat = 0.2;  // Minecraft's creative delays (5 and 4 ticks)

bool replaceable(const BlockType& type) {
  return type.shape == BlockShape::None || type.shape == BlockShape::Liquid ||
         type.shape == BlockShape::Cross;
}

}  // namespace

void Game::useBlocks(const FrameInput& in, double dt) {
  breakCooldown_ -= dt;
  placeCooldown_ -= dt;
  target_ = targetBlock(world_.world(), player_.eye(), player_.forward());
  // A prop in front of the targeted block (or in the open) is what the crosshair is on: breaking
  // removes it, and no block is used through it.
  const auto prop = props_->placed().pick(player_.eye(), player_.forward(), kReach);
  targetProp_.reset();
  // A prop standing in a plant's cell is entered where the cell is: the prop wins the tie.
  if (prop && (!target_ || prop->distance <= target_->distance + 1e-9)) targetProp_ = prop->index;
  if (targetProp_) {
    if (in.wasPressed(MouseButton::Left) || (in.isHeld(MouseButton::Left) && breakCooldown_ <= 0.0)) {
      logInfo("removed the prop " + props_->prop(*targetProp_).model);
      props_->remove(*targetProp_);
      renderer_.setPropNeeds(props_->placed().gpu().needs());
      targetProp_.reset();
      breakCooldown_ = kBreakRepeat;
    }
    return;
  }
  if (!target_) return;
  if (in.wasPressed(MouseButton::Middle)) {
    const BlockId picked = pickedBy(world_.world(), target_->block);
    const auto slot = std::find(hotbar_.begin(), hotbar_.end(), picked);
    if (slot != hotbar_.end())
      selected_ = static_cast<int>(slot - hotbar_.begin());
    else
      hotbar_[static_cast<std::size_t>(selected_)] = picked;
  }
  const bool breakNow =
      in.wasPressed(MouseButton::Left) || (in.isHeld(MouseButton::Left) && breakCooldown_ <= 0.0);
  if (breakNow) {
    for (const BlockPos& cell : brokenBy(world_.world(), target_->block)) editBlock(cell, kAir);
    breakCooldown_ = kBreakRepeat;
    target_ = targetBlock(world_.world(), player_.eye(), player_.forward());
    return;
  }
  const bool placeNow =
      in.wasPressed(MouseButton::Right) || (in.isHeld(MouseButton::Right) && placeCooldown_ <= 0.0);
  if (!placeNow) return;
  placeCooldown_ = kPlaceRepeat;
  // A plant under the crosshair is replaced, as in Minecraft; anything else gets the block beside it.
  // A block that opens is opened or closed instead.
  if (const auto used = useOf(world_.world(), target_->block, player_.forward()); !used.empty()) {
    for (const Placement& cell : used) editBlock(cell.at, cell.state);
    return;
  }
  // A plant under the crosshair is replaced, as in Minecraft; anything else gets the block beside it.
  const BlockPos at =
      replaceable(blocks_[world_.world().getBlock(target_->block)]) ? target_->block : target_->place;
  const glm::dvec3 hit = player_.eye() + player_.forward() * target_->distance;
  const std::vector<Placement> cells = placementOf(
      world_.world(), hotbar_[static_cast<std::size_t>(selected_)], *target_, at, hit, player_.forward());
  for (const Placement& cell : cells) {
    if (cell.at == target_->block && !replaceable(blocks_[world_.world().getBlock(cell.at)]))
      continue;  // joins it
    if (!inWorldHeight(cell.at.y) || !replaceable(blocks_[world_.world().getBlock(cell.at)])) return;
    if (blocksPlayer(cell.at, cell.state)) return;  // never inside the player
    const BlockType& type = blocks_[cell.state];
    if ((type.shape == BlockShape::Cross || type.shape == BlockShape::Torch) &&
        !world_.world().opaqueCubes()[world_.world().getBlock(cell.at.offset(0, -1, 0))]) {
      return;  // torches and plants stand on a full block
    }
  }
  for (const Placement& cell : cells) editBlock(cell.at, cell.state);
}

bool Game::blocksPlayer(const BlockPos& at, BlockId state) const {
  const Box body = player_.box();
  for (const Box& b : collisionBoxes(shapes_, state, at)) {
    if (overlaps(b, body)) return true;
  }
  return false;
}

void Game::placeProp(const std::string& model) {
  if (model.empty()) {
    logWarning("no prop to place: put .gltf or .glb files in " + (world_.dir() / "props").string() +
               " and choose one in the menu's Props tab");
    return;
  }
  if (!target_) {
    logWarning("no prop placed: look at a block with room beside it");
    return;
  }
  // As for blocks: a plant under the crosshair gives its own cell, anything else the cell beside it.
  const BlockPos at =
      replaceable(blocks_[world_.world().getBlock(target_->block)]) ? target_->block : target_->place;
  if (!inWorldHeight(at.y) || !replaceable(blocks_[world_.world().getBlock(at)])) {
    logWarning("no prop placed: look at a block with room beside it");
    return;
  }
  try {
    const LevelProp prop = props_->standingIn(model, at);
    const WorldBounds box = props_->boundsOf(prop);
    const Box body = player_.box();
    if (body.min.x < box.max.x && body.max.x > box.min.x && body.min.y < box.max.y &&
        body.max.y > box.min.y && body.min.z < box.max.z && body.max.z > box.min.z) {
      logWarning("no prop placed: it would stand in the player");
      return;
    }
    // The prop takes a plant's place, as a block would.
    if (world_.world().getBlock(at) != kAir) editBlock(at, kAir);
    props_->place(prop, world_.world(), world_.light());
    renderer_.setPropNeeds(props_->placed().gpu().needs());
    logInfo("placed " + model);
  } catch (const Error& e) {
    logError(std::string("prop not placed: ") + e.what());
  }
}

std::vector<std::string> Game::propFiles() const {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(world_.dir() / "props", ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) {
      files.push_back((std::filesystem::path("props") / entry.path().filename()).string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool Game::editBlock(const BlockPos& pos, BlockId state) {
  if (!world_.setBlock(pos, state)) return false;
  edits_.push_back({pos, blocks_.stateName(state)});
  for (const auto& [at, connected] : connectionUpdates(world_.world(), pos)) {
    if (world_.setBlock(at, connected)) edits_.push_back({at, blocks_.stateName(connected)});
  }
  return true;
}

}  // namespace terrasol::session
