#include "light/section_solver.h"

#include <bit>

#include "light/propagator.h"

namespace terrasol::light {

void SectionSolver::begin(const BlockId* blocks, int mask, const std::uint8_t* attenuations) {
  blocks_ = blocks;
  mask_ = mask;
  attenuations_ = attenuations;
  attenuation_.fill(0);
  reads_ = 0;
}

void SectionSolver::solve() {
  // Highest level first: a cell raised while its bucket waits is skipped there, it spreads from its
  // higher bucket. Spreading only fills lower buckets, so each bucket is final when its turn comes.
  for (int level = kMaxLight; level >= 2; --level) {
    const std::uint16_t* bucket = buckets_[static_cast<std::size_t>(level)].data();
    for (int k = 0; k < counts_[level]; ++k) {
      const int i = bucket[k];
      if (levels_[static_cast<std::size_t>(i)] != level) continue;
      const std::uint8_t inside = kInSection[static_cast<std::size_t>(i)];
      if (inside & kInterior) {
        enter(i - 1, level);
        enter(i + 1, level);
        enter(i - kChunkArea, level);
        enter(i + kChunkArea, level);
        enter(i - kChunkSize, level);
        enter(i + kChunkSize, level);
        continue;
      }
      for (unsigned dirs = inside & kAllDirections; dirs != 0; dirs &= dirs - 1) {
        enter(i + kIndexStep[std::countr_zero(dirs)], level);
      }
    }
    counts_[level] = 0;
  }
}

}  // namespace terrasol::light
