#pragma once
// The sections whose light (or halo light) changed since the mesher last asked. Updates only append
// keys, repeats and all, which costs a store where a hash set cost a lookup and an allocation per
// new section (0.5 of a torch's 15.8 us); repeats go when the keys are taken, or when they pile up
// between takes.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "world/coords.h"

namespace terrasol::light {

class ChangedSections {
 public:
  void add(int chunkX, int section, int chunkZ) {
    keys_.push_back(key(chunkX, section, chunkZ));
    if (keys_.size() >= limit_) {
      unique();
      limit_ = std::max(kMinLimit, 2 * keys_.size());  // amortized: at most twice the distinct keys
    }
  }
  // Each section once, in key order.
  std::vector<SectionPos> take() {
    unique();
    std::vector<SectionPos> sections;
    sections.reserve(keys_.size());
    for (const std::uint64_t k : keys_) sections.push_back(fromKey(k));
    keys_.clear();
    limit_ = kMinLimit;
    return sections;
  }

  // 27 bits each of chunk x and z (the world border is at chunk +-1 875 000, well inside +-2^26)
  // and 5 bits of section index.
  static constexpr std::uint64_t key(int chunkX, int section, int chunkZ) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(chunkX) & 0x7FFFFFF) << 32) |
           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(chunkZ) & 0x7FFFFFF) << 5) |
           static_cast<std::uint64_t>(section & 31);
  }
  static constexpr SectionPos fromKey(std::uint64_t key) {
    auto signExtend27 = [](std::uint64_t v) {
      return static_cast<int>(static_cast<std::int32_t>(static_cast<std::uint32_t>(v << 5)) >> 5);
    };
    return {signExtend27((key >> 32) & 0x7FFFFFF), static_cast<int>(key & 31),
            signExtend27((key >> 5) & 0x7FFFFFF)};
  }

 private:
  static constexpr std::size_t kMinLimit = 4096;

  void unique() {
    std::sort(keys_.begin(), keys_.end());
    keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
  }

  std::vector<std::uint64_t> keys_;
  std::size_t limit_ = kMinLimit;
};

static_assert(ChangedSections::fromKey(ChangedSections::key(-1'875'000, 23, 1'875'000)) ==
              SectionPos{-1'875'000, 23, 1'875'000});

}  // namespace terrasol::light
