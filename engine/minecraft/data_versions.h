#pragma once
// Minecraft Java's DataVersion numbers at which its world format changed (minecraft.wiki's
// Data version table; worlds/FORMAT.md in the test data collects them with their sources).

namespace terrasol {

inline constexpr int kDataVersion1_13 = 1519;  // the flattening: named block states in palettes
inline constexpr int kDataVersion1_14 = 1952;
// 20w17a: a block index no longer spans two longs.
inline constexpr int kDataVersionUnspannedLongs = 2529;
inline constexpr int kDataVersion1_17 = 2724;
// 21w43a: chunks lose their Level wrapper; sections, block_states and biome palettes.
inline constexpr int kDataVersion1_18 = 2844;

}  // namespace terrasol
