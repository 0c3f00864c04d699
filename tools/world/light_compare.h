#pragma once
// Terrasol's light against the light a Minecraft save keeps: every full chunk of the save is put in a
// World and lit by Terrasol's LightEngine, then each cell of the chunks whose eight neighbours are
// full too (so light from outside is the same in both) is compared with what Minecraft stored.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "world/block_registry.h"
#include "world/coords.h"

namespace terrasol {

struct ChannelComparison {
  std::uint64_t equal = 0;
  // Terrasol's level minus Minecraft's, -15..15 at index + 15.
  std::array<std::uint64_t, 31> differences{};
  double equalPercent(std::uint64_t cells) const {
    return cells ? 100.0 * static_cast<double>(equal) / static_cast<double>(cells) : 0.0;
  }
};

// One cell that differs, for looking at.
struct LightDifference {
  BlockPos pos;
  int ours, theirs;
  bool sky;
};

struct LightComparison {
  std::uint64_t chunks = 0;  // compared: full, stored light, eight full neighbours
  std::uint64_t cells = 0;
  ChannelComparison sky, block;
  std::vector<LightDifference> samples;  // the first differences found, up to a few hundred
};

LightComparison compareLight(const std::filesystem::path& save, const BlockRegistry& blocks);

}  // namespace terrasol
