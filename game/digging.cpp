#include "digging.h"

#include <algorithm>
#include <limits>

namespace terrasol {

float Digging::progressPerTick(float hardness, bool hampered) {
  if (hardness < 0.0f) return 0.0f;  // kUnbreakable
  if (hardness == 0.0f) return std::numeric_limits<float>::infinity();
  return kToolSpeed / (hampered ? kHamperedSlowdown : 1.0f) / hardness / 30.0f;
}

Digging::Tick Digging::start(const BlockPos& at, float perTick) {
  progress_ = 0.0f;
  ticks_ = 0;
  if (perTick >= 1.0f) {  // no hit and no pause after
    block_.reset();
    return {.hit = false, .broken = true};
  }
  block_ = at;
  return {};
}

Digging::Tick Digging::tick(const DigInput& in) {
  const float perTick = progressPerTick(in.hardness, in.hampered);
  // A click starts on the block; one that breaks it ends the tick, as Minecraft's startAttack.
  if (in.clicked && in.target && block_ != in.target) {
    if (const Tick t = start(*in.target, perTick); t.broken) return t;
  }
  if (!in.held || !in.target) {  // let go (a click and release in one tick digs nothing)
    block_.reset();
    return {};
  }
  if (delay_ > 0) {  // counted down only while held
    --delay_;
    return {};
  }
  if (block_ != in.target) return start(*in.target, perTick);
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
