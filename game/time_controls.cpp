#include "time_controls.h"

#include <algorithm>
#include <iterator>

#include "core/day_cycle.h"

namespace terrasol {

std::int64_t TimeControls::nextPreset(std::int64_t time) {
  constexpr std::int64_t kPresets[] = {kSunrise + 1000, kNoon, kSunset,
                                       kMidnight};  // morning, noon, sunset, midnight
  const std::int64_t day = time / kTicksPerDay, ofDay = time % kTicksPerDay;
  const auto next =
      std::find_if(std::begin(kPresets), std::end(kPresets), [&](std::int64_t t) { return t > ofDay; });
  return next == std::end(kPresets) ? (day + 1) * kTicksPerDay + kPresets[0] : day * kTicksPerDay + *next;
}

}  // namespace terrasol
