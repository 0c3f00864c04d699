#pragma once
// Digging in survival, tick by tick, as Minecraft's MultiPlayerGameMode does it: holding the button on
// a block adds speed / hardness / 30 to its progress each tick until it reaches 1 and the block
// breaks, with a hit sound every 4th tick and a crack growing through 10 stages; looking away starts
// afresh, and after a break the next block waits 5 ticks. Plain C++.

#include <optional>

#include "assets/crack_textures.h"
#include "world/block.h"
#include "world/coords.h"

namespace terrasol {

// A block hit while dug, as it was when hit (it may break in the same tick).
struct DigHit {
  BlockPos at;
  BlockId state = kAir;
};

class Digging {
 public:
  // The player digs as with the right tool of iron (Minecraft's speed 6): stone takes 8 ticks,
  // dirt 3, a log 10, obsidian 250; leaves and plants break at once.
  static constexpr float kToolSpeed = 6.0f;
  static constexpr int kHitEvery = 4, kDelayAfterBreak = 5;

  struct Tick {
    bool hit = false;     // the hit sound plays this tick
    bool broken = false;  // the block breaks this tick
  };

  // One tick: the button `held` on `target` (none: nothing in reach) whose hardness is `hardness`.
  Tick tick(bool held, const std::optional<BlockPos>& target, float hardness);

  // The block being dug and its crack, 0..kCrackStages - 1 (assets/crack_textures.h); none while
  // nothing is dug.
  std::optional<BlockPos> block() const { return block_; }
  std::optional<int> crackStage() const;

  // What a tick adds to the progress on a block of `hardness`: 0 for an unbreakable one.
  static float progressPerTick(float hardness);

 private:
  std::optional<BlockPos> block_;
  float progress_ = 0.0f;
  int ticks_ = 0;  // ticks on this block: the hit sound's count
  int delay_ = 0;  // ticks still to wait after a break
};

}  // namespace terrasol
