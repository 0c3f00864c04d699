#pragma once
// The cloud layer's map from the pack stack: the topmost pack's textures/environment/clouds.png, its
// alpha read as coverage (core/cloud_layer.h), as Minecraft reads it.

#include <vector>

#include "assets/resource_pack.h"
#include "assets/texture_loader.h"
#include "core/cloud_layer.h"

namespace terrasol {

inline constexpr const char* kCloudsTexture = "assets/minecraft/textures/environment/clouds.png";

// Empty (no clouds) where no pack has one; an unreadable one is a problem naming the file, and empty too.
CloudMap loadCloudMap(const PackStack& packs, std::vector<PackProblem>& problems);

}  // namespace terrasol
