#pragma once
// The player's own sounds, by Minecraft's rules: a step of the block underfoot each time the
// distance moved passes the next whole step (0.6 of a block's travel counts as one, so a step every
// 1.67 blocks; distance in the air counts, and the step comes when a foot finds a block), none while
// sneaking on the ground, flying or in water; a fall's thud on landing from more than 3 blocks.
// Plain C++, called after each of the player's ticks.

#include <glm/geometric.hpp>
#include <vector>

#include "block_sound_cues.h"
#include "player.h"

namespace terrasol {

class Footsteps {
 public:
  static constexpr double kStepScale = 0.6;  // Minecraft's moveDist per block walked
  static constexpr double kQuietFall = 3.0;  // blocks fallen without a thud
  static constexpr double kTeleport = 5.0;   // blocks in a tick: more than falling's 3.92 is a teleport

  void tick(const Player& player, const World& world, const BlockSoundTable& sounds, std::int64_t tick,
            std::vector<SoundCue>& out);

 private:
  // The block whose sound a foot at `feet` makes: the cell just below, or the one under it for a
  // fence's top half; none over air.
  static std::optional<std::pair<BlockId, BlockPos>> underfoot(const World& world,
                                                               const BlockSoundTable& sounds,
                                                               glm::dvec3 feet);

  bool started_ = false, wasOnGround_ = false;
  glm::dvec3 last_{0.0};
  double walked_ = 0.0, nextStep_ = 1.0, peakY_ = 0.0;
};

}  // namespace terrasol
