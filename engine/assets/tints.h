#pragma once
// Biome tints for grey textures: the packs' colormaps (assets/minecraft/textures/colormap/grass.png
// and foliage.png), looked up the way Minecraft does for a biome's temperature and downfall.

#include <glm/vec3.hpp>
#include <vector>

#include "assets/image.h"
#include "assets/resource_pack.h"
#include "assets/texture_loader.h"
#include "core/tint.h"

namespace terrasol {

struct BiomeColormaps {
  // sRGB, RGBA8. Where no pack has a colormap, 1 x 1 of Minecraft's plains colour (kDefaultGrass, ...).
  Image grass, foliage;
};

// Colormap texel for a climate: temperature and downfall clamped to 0..1, downfall scaled by
// temperature, then x = (1 - temperature), y = (1 - downfall) across the map.
glm::vec3 sampleColormap(const Image& colormap, float temperature, float downfall);

// The topmost pack's colormaps. An unreadable one is a problem and falls back to the default.
BiomeColormaps loadColormaps(const PackStack& packs, std::vector<PackProblem>& problems);

// The sRGB colour `tint` multiplies a texture by at a tint climate, as the block shaders compute it
// (the colormap's texel, water by temperature, fixed leaf colours; white for Tint::None).
glm::vec3 tintColour(const BiomeColormaps& maps, Tint tint, TintClimate climate = kPlainsTint);

}  // namespace terrasol
