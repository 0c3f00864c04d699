#pragma once
// What the player does to the world with the mouse: the block or prop under the crosshair, breaking
// (left: at once with Minecraft's creative repeat delay, or dug tick by tick in survival), using or
// placing the held block (right), picking (middle), and placing props. Owns the hotbar the held block
// comes from.

#include <optional>
#include <string>

#include "controls.h"
#include "digging.h"
#include "hotbar.h"
#include "play_world.h"
#include "render/frame_inputs.h"
#include "targeting.h"

namespace terrasol {

class BlockInteraction {
 public:
  explicit BlockInteraction(const BlockContent& content) : content_(content), hotbar_(content.blocks) {}

  // This frame's clicks (`dt` seconds since the last) on what the crosshair is on.
  void update(const FrameInput& in, double dt, PlayWorld& world);
  // Survival digging: blocks take their time to break (Digging) instead of breaking at a click.
  void setSurvivalDigging(bool on) { survival_ = on; }
  // One world tick of survival digging with the button `held` (and any click since the last tick);
  // the block hit this tick, whose hit sound plays. Nothing in creative.
  std::optional<DigHit> digTick(bool held, PlayWorld& world);
  // The crack on the block being dug.
  std::optional<BlockCrack> crack() const;
  // Stands `model` (relative to the world folder, or absolute) in the targeted free cell; says why
  // not in the log when it cannot.
  void placeProp(const std::string& model, PlayWorld& world);

  Hotbar& hotbar() { return hotbar_; }
  const Hotbar& hotbar() const { return hotbar_; }
  const std::optional<Target>& target() const { return target_; }
  // The box the outline goes round: the targeted prop, or the targeted block.
  std::optional<WorldBox> outline(const PlayWorld& world) const;

 private:
  void useTargetedProp(const FrameInput& in, PlayWorld& world);
  void placeHeld(PlayWorld& world);
  void breakTarget(PlayWorld& world);
  // Whether a plant, liquid or air: what placing a block or prop replaces.
  bool replaceable(const World& world, const BlockPos& at) const;
  // Whether `state` placed at `at` would stand in the player (its collision boxes).
  bool blocksPlayer(const Player& player, const BlockPos& at, BlockId state) const;

  const BlockContent& content_;
  Hotbar hotbar_;
  std::optional<Target> target_;
  std::optional<int> targetProp_;  // a drawn prop nearer than the targeted block: GameProps index
  double breakCooldown_ = 0.0, placeCooldown_ = 0.0;
  bool survival_ = false;
  bool clicked_ = false;  // the break button pressed since the last tick: a click between ticks digs
  Digging digging_;
};

}  // namespace terrasol
