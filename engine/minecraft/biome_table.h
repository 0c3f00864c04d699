#pragma once
// Minecraft's biomes as column tints: each biome's temperature and downfall, which place its grass,
// foliage and water on the packs' colormaps (core/tint.h), and the colours some biomes have of their
// own (badlands, swamps, dark forest, cherry grove, pale garden; each biome's water). Names as chunks
// from 1.18 on store them; numeric ids as 1.13 to 1.17 chunks do. Temperatures and the numeric ids
// come from minecraft-data (MIT, data/LICENSE.minecraft-data: 1.21.11 and 1.16.2 biomes.json, which
// gives 1.16's downfall too); today's downfalls and the colours are those of Minecraft's worldgen
// biome definitions.

#include <cstdint>
#include <optional>
#include <string_view>

#include "core/tint.h"

namespace terrasol {

// A biome of this table, what a chunk's biome cells hold.
using MinecraftBiome = std::uint16_t;

// "minecraft:plains" or "plains"; nothing for a biome Minecraft does not have (a mod's).
std::optional<MinecraftBiome> minecraftBiome(std::string_view name);
// A 1.13–1.17 numeric biome id; nothing for an unknown one.
std::optional<MinecraftBiome> minecraftBiome(int id);
// What an unknown biome is taken for.
MinecraftBiome minecraftPlains();

// The tint of block column (x, z) in `biome`, before blending: swamps' grass takes one of two colours
// by Minecraft's biome noise there.
ColumnTint minecraftBiomeTint(MinecraftBiome biome, int x, int z);

}  // namespace terrasol
