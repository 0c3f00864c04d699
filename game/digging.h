#pragma once
// Digging in survival, tick by tick, as Minecraft's MultiPlayerGameMode does it: a click starts on a
// block (breaking it at once where one tick's progress would), and while the button is held each tick
// adds speed / hardness / 30 until the progress reaches 1 and the block breaks, with a hit sound every
// 4th tick and a crack growing through 10 stages. Looking at another block starts on it (that tick
// adds nothing); letting go stops; after a break 5 held ticks pass before the next block is started.
// Plain C++.

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

// The player's part in one tick of digging.
struct DigInput {
  bool clicked = false;            // the button went down since the last tick
  bool held = false;               // the button is down now
  std::optional<BlockPos> target;  // the block under the crosshair; none out of reach
  float hardness = 0.0f;           // the target's
  bool hampered = false;           // off the ground, or the eyes under water: 5 times slower
};

class Digging {
 public:
  // The player digs as with the right tool of iron (Minecraft's speed 6): stone takes 8 ticks,
  // dirt 3, a log 10, obsidian 250; leaves and plants break at once.
  static constexpr float kToolSpeed = 6.0f, kHamperedSlowdown = 5.0f;
  static constexpr int kHitEvery = 4, kDelayAfterBreak = 5;

  struct Tick {
    bool hit = false;     // the hit sound plays this tick
    bool broken = false;  // the target breaks this tick
  };

  Tick tick(const DigInput& in);

  // The block being dug and its crack, 0..kCrackStages - 1 (assets/crack_textures.h); none before
  // the first progress.
  std::optional<BlockPos> block() const { return block_; }
  std::optional<int> crackStage() const;

  // What a tick adds to the progress on a block of `hardness`: 0 for an unbreakable one, infinity for
  // one that breaks at once.
  static float progressPerTick(float hardness, bool hampered = false);

 private:
  // Minecraft's startDestroyBlock: broken at once, or begun with no progress.
  Tick start(const BlockPos& at, float perTick);

  std::optional<BlockPos> block_;  // being dug
  float progress_ = 0.0f;
  int ticks_ = 0;  // held ticks on this block: the hit sound's count
  int delay_ = 0;  // held ticks still to wait after a break
};

}  // namespace terrasol
