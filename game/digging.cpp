#include "digging.h"

#include <algorithm>
#include <limits>

#include "world/block.h"

namespace terrasol {

float Digging::progressPerTick(float hardness) {
  if (hardness < 0.0f) return 0.0f;  // kUnbreakable
  if (hardness == 0.0f) return std::numeric_limits<float>::infinity();
  return kToolSpeed / hardness / 30.0f;
}

Digging::Tick Digging::tick(bool held, const std::optional<BlockPos>& target, float hardness) {
  if (delay_ > 0) {  // counted down held or not: a fresh click waits too
    --delay_;
    block_.reset();
    return {};
  }
  if (!held || !target) {
    block_.reset();
    return {};
  }
  const float perTick = progressPerTick(hardness);
  if (block_ != target) {
    block_ = target;
    progress_ = 0.0f;
    ticks_ = 0;
    if (perTick >= 1.0f) {  // at once, with no hit and no pause after (Minecraft's instant break)
      block_.reset();
      return {.hit = false, .broken = true};
    }
  }
  Tick out;
  out.hit = ticks_ % kHitEvery == 0;
  ++ticks_;
  progress_ += perTick;
  if (progress_ >= 1.0f) {
    out.broken = true;
    block_.reset();
    delay_ = kDelayAfterBreak;
  }
  return out;
}

std::optional<int> Digging::crackStage() const {
  if (!block_ || progress_ <= 0.0f) return std::nullopt;
  return std::min(static_cast<int>(progress_ * static_cast<float>(kCrackStages)), kCrackStages - 1);
}

}  // namespace terrasol
