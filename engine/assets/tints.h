#pragma once
// Biome tints for grey textures (grass, foliage, water), from the packs' colormaps
// (assets/minecraft/textures/colormap/grass.png and foliage.png) when they have them, looked up the
// way Minecraft does for a biome's temperature and downfall.

#include <vector>

#include <glm/vec3.hpp>

#include "assets/image.h"
#include "assets/resource_pack.h"
#include "assets/texture_loader.h"

namespace terrasol {

struct BiomeTints {
  glm::vec3 grass, foliage, water;  // sRGB 0..1, multiplied onto the grey texture
};

// Minecraft's defaults when a pack has no colormap (the plains colours), and its usual water colour.
inline constexpr glm::vec3 kDefaultGrass{0x91 / 255.0f, 0xBD / 255.0f, 0x59 / 255.0f};
inline constexpr glm::vec3 kDefaultFoliage{0x77 / 255.0f, 0xAB / 255.0f, 0x2F / 255.0f};
inline constexpr glm::vec3 kDefaultWater{0x3F / 255.0f, 0x76 / 255.0f, 0xE4 / 255.0f};

// Colormap texel for a climate: temperature and downfall clamped to 0..1, downfall scaled by
// temperature, then x = (1 - temperature), y = (1 - downfall) across the map.
glm::vec3 sampleColormap(const Image& colormap, float temperature, float downfall);

// Plains climate by default (temperature 0.8, downfall 0.4). Unreadable colormaps are problems and
// fall back to the defaults.
BiomeTints loadTints(const PackStack& packs, std::vector<PackProblem>& problems, float temperature = 0.8f,
                     float downfall = 0.4f);

}  // namespace terrasol
