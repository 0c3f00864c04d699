#pragma once
// Random picks that depend only on a block's position, so a world looks the same every time it is
// drawn: which of a blockstate's weighted models a cell shows. Shared by the blockstate reader and
// the mesher.

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>

namespace terrasol {

// Minecraft's position seed for random model picks (Mth.getSeed), in unsigned arithmetic where
// Java's wraps.
constexpr std::int64_t positionSeed(glm::ivec3 pos) {
  std::uint64_t l = static_cast<std::uint64_t>(static_cast<std::int64_t>(pos.x) * 3129871) ^
                    static_cast<std::uint64_t>(static_cast<std::int64_t>(pos.z) * 116129781ll) ^
                    static_cast<std::uint64_t>(static_cast<std::int64_t>(pos.y));
  l = l * l * 42317861ull + l * 11ull;
  return static_cast<std::int64_t>(l) >> 16;
}

// The index of a pick among choices of these weights (each >= 1), from `seed`: choice i is taken
// with probability weights[i] / sum. The seed is mixed first (SplitMix64's finaliser), as
// neighbouring positions' seeds differ in few bits.
constexpr std::size_t weightedPick(std::span<const int> weights, std::int64_t seed) {
  if (weights.size() <= 1) return 0;
  std::uint64_t z = static_cast<std::uint64_t>(seed);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  std::uint64_t total = 0;
  for (const int w : weights) total += static_cast<std::uint64_t>(w);
  std::uint64_t at = z % total;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (at < static_cast<std::uint64_t>(weights[i])) return i;
    at -= static_cast<std::uint64_t>(weights[i]);
  }
  return weights.size() - 1;
}

}  // namespace terrasol
