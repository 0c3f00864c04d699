#include "footsteps.h"

#include <cmath>

namespace terrasol {

std::optional<std::pair<BlockId, BlockPos>> Footsteps::underfoot(const World& world,
                                                                 const BlockSoundTable& sounds,
                                                                 glm::dvec3 feet) {
  const BlockPos below{static_cast<int>(std::floor(feet.x)), static_cast<int>(std::floor(feet.y - 0.2)),
                       static_cast<int>(std::floor(feet.z))};
  for (const BlockPos& at : {below, below.offset(0, -1, 0)}) {
    const BlockId state = world.getBlock(at);
    if (!sounds.silent(state)) return std::pair{state, at};
  }
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
  if (!grounded) {
    peakY_ = std::max(peakY_, now.y);
    wasOnGround_ = false;
    return;
  }
  if (!wasOnGround_ && peakY_ - now.y > kQuietFall) {
    if (const auto foot = underfoot(world, sounds, now)) {
      if (auto c = sounds.cue(foot->first, foot->second, BlockAction::Fall, tick))
        out.push_back(std::move(*c));
    }
  }
  wasOnGround_ = true;
  peakY_ = now.y;
  const double horizontal = std::hypot(moved.x, moved.z);
  walked_ += horizontal * kStepScale;
  if (walked_ <= nextStep_) return;
  nextStep_ = std::floor(walked_) + 1.0;
  if (player.sneaking()) return;
  if (const auto foot = underfoot(world, sounds, now)) {
    if (auto c = sounds.cue(foot->first, foot->second, BlockAction::Step, tick)) out.push_back(std::move(*c));
  }
}

}  // namespace terrasol
