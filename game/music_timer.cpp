#include "music_timer.h"

#include "core/day_cycle.h"

namespace terrasol {

bool MusicTimer::night(std::int64_t ticks) {
  const std::int64_t t = ((ticks % kTicksPerDay) + kTicksPerDay) % kTicksPerDay;
  return t >= kSunset + 1000 && t < kTicksPerDay - 1000;
}

std::optional<std::string_view> MusicTimer::tick(bool playing, bool night, std::mt19937& random) {
  if (playing) {
    wasPlaying_ = true;
    return std::nullopt;
  }
  if (wasPlaying_) {
    wasPlaying_ = false;
    delay_ = std::uniform_int_distribution<int>(kMinDelay, kMaxDelay)(random);
  }
  if (--delay_ > 0) return std::nullopt;
  delay_ = kMaxDelay;  // until the track is heard to play; a track that cannot play waits this long
  return night ? kNight : kDay;
}

}  // namespace terrasol
