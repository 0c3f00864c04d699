#pragma once
// Minecraft's biomes as tint climates: each biome's temperature and downfall, which place its grass,
// foliage and water on the packs' colormaps (core/tint.h). Names as chunks from 1.18 on store them;
// numeric ids as 1.13 to 1.17 chunks do. Temperatures and the numeric ids come from minecraft-data
// (MIT, data/LICENSE.minecraft-data: 1.21.11 and 1.16.2 biomes.json, which gives 1.16's downfall too);
// today's downfalls are those of Minecraft's worldgen biome definitions.

#include <optional>
#include <string_view>

#include "core/tint.h"

namespace terrasol {

// "minecraft:plains" or "plains"; nothing for a biome Minecraft does not have (a mod's).
std::optional<TintClimate> minecraftBiomeTint(std::string_view name);
// A 1.13–1.17 numeric biome id; nothing for an unknown one.
std::optional<TintClimate> minecraftBiomeTint(int id);

}  // namespace terrasol
