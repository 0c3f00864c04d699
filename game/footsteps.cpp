#include "footsteps.h"

#include <cmath>

namespace terrasol {

std::optional<std::pair<BlockId, BlockPos>> Footsteps::underfoot(const World& world,
                                                                 const BlockSoundTable& sounds,
                                                                 glm::dvec3 feet) {
  const BlockPos below = BlockPos::containing(feet.x, feet.y - 0.2, feet.z);
  const BlockId state = world.getBlock(below);
  if (!sounds.silent(state)) return std::pair{state, below};
  // On a fence or wall the foot is a cell above the block it stands on (Minecraft's getOnPos).
  const BlockPos post = below.offset(0, -1, 0);
  const BlockId postState = world.getBlock(post);
  if (world.blocks()[postState].collisionHeight > 16 && !sounds.silent(postState))
    return std::pair{postState, post};
  return std::nullopt;
}

void Footsteps::tick(const Player& player, const World& world, const BlockSoundTable& sounds,
                     std::int64_t tick, std::vector<SoundCue>& out) {
  const glm::dvec3 now = player.position();
  const bool grounded = player.onGround() && !player.flying && !player.inWater();
  if (!started_ || player.flying || player.inWater()) {
    started_ = true;
    last_ = now;
    peakY_ = now.y;
    wasOnGround_ = grounded;
    return;
  }
  const glm::dvec3 moved = now - last_;
  last_ = now;
  if (glm::length(moved) > kTeleport) {  // moved, not walked or fallen: start afresh
    peakY_ = now.y;
    wasOnGround_ = grounded;
    return;
  }
  if (grounded && !wasOnGround_ && peakY_ - now.y > kQuietFall) {
    if (const auto foot = underfoot(world, sounds, now)) {
      if (auto c = sounds.cue(foot->first, foot->second, BlockAction::Fall, tick))
        out.push_back(std::move(*c));
    }
  }
  peakY_ = grounded ? now.y : std::max(peakY_, now.y);
  wasOnGround_ = grounded;
  // Minecraft counts the distance in the air too, and steps once a foot finds a block: a running
  // jump lands with a step. A player sneaking on the ground moves without a sound or a count.
  if (player.sneaking() && grounded) return;
  walked_ += std::hypot(moved.x, moved.z) * kStepScale;
  if (walked_ <= nextStep_) return;
  const auto foot = underfoot(world, sounds, now);
  if (!foot) return;  // in the air: the step waits for the ground
  nextStep_ = std::floor(walked_) + 1.0;
  if (auto c = sounds.cue(foot->first, foot->second, BlockAction::Step, tick)) out.push_back(std::move(*c));
}

}  // namespace terrasol
