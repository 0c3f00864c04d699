#pragma once
// Minecraft's biome blend: a column's grass, foliage and water colours are the mean over the 5 x 5
// columns around it (the game's default "biome blend" of 5 x 5), reaching into neighbouring chunks,
// so biomes fade into each other over five blocks instead of stepping at their 4-block cells.

#include <array>

#include "core/tint.h"
#include "world/chunk.h"

namespace terrasol {

inline constexpr int kBiomeBlendRadius = 2;

using ColumnTints = std::array<ColumnTint, kChunkArea>;  // by columnIndex

// The chunk's unblended tints.
ColumnTints columnTintsOf(const Chunk& chunk);

// Sets `chunk`'s tints from the unblended ones of the chunk and its eight neighbours: `around[(dz + 1)
// * 3 + dx + 1]`, null for a neighbour the world does not have (the centre chunk's edge columns stand
// in). The centre must not be null. The mean climate, and each biome's own colours weighted by how
// strongly each column has them.
void blendBiomeTints(const std::array<const ColumnTints*, 9>& around, Chunk& chunk);

}  // namespace terrasol
