#pragma once
// Biome tints for grey textures: the packs' colormaps (assets/minecraft/textures/colormap/grass.png
// and foliage.png), read into the palette the mesher and the CPU tools colour blocks with.

#include <vector>

#include "assets/image.h"
#include "assets/resource_pack.h"
#include "assets/texture_loader.h"
#include "core/tint_palette.h"

namespace terrasol {

// An image's colours, alpha dropped.
Colormap colormapOf(const Image& image);

// The topmost pack's colormaps; where none has one, Minecraft's plains colours. An unreadable one is
// a problem and falls back the same way.
TintPalette loadColormaps(const PackStack& packs, std::vector<PackProblem>& problems);

}  // namespace terrasol
