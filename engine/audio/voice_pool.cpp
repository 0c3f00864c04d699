#include "audio/voice_pool.h"

#include <algorithm>

namespace terrasol {

std::optional<int> VoicePool::claim(float loudness) {
  if (loudness_.empty()) return std::nullopt;
  const auto free = std::find(loudness_.begin(), loudness_.end(), kFree);
  const auto slot = free != loudness_.end() ? free : std::min_element(loudness_.begin(), loudness_.end());
  if (free == loudness_.end() && *slot >= loudness) return std::nullopt;
  *slot = std::max(loudness, 0.0f);
  return static_cast<int>(slot - loudness_.begin());
}

int VoicePool::busyCount() const {
  return static_cast<int>(
      std::count_if(loudness_.begin(), loudness_.end(), [](float l) { return l != kFree; }));
}

}  // namespace terrasol
