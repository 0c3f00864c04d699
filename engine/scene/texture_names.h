#pragma once
// The names a pack may give a block texture: today's, then the older ones Minecraft renamed it from,
// so a pack made for an older Minecraft still covers the default pack's.

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace terrasol {

// Textures Minecraft renamed: (today's name, the older one).
std::span<const std::pair<std::string_view, std::string_view>> renamedTextures();
// Texture names with the older names a pack may give them after each.
std::vector<std::string> withOlderNames(const std::vector<std::string>& names);
// A model's texture reference ("block/oak_planks") as the names the loader looks for: today's
// ("oak_planks"), then older ones.
std::vector<std::string> candidatesOf(const std::string& texture);

}  // namespace terrasol
