#pragma once
// The shader packs the menu offers: the folders (with a shaders/ folder inside) and .zip files in the
// game's shaderpacks/ folder beside worlds/, and those shipped with the game, each once, by name.

#include <filesystem>
#include <vector>

namespace terrasol {

// Where the game looks for shader packs, relative to the current directory like kWorldsDir.
inline constexpr const char* kShaderPacksDir = "shaderpacks";

// Packs in `dirs` (missing folders are skipped), sorted by file name, a pack reached twice listed once.
std::vector<std::filesystem::path> findShaderPacks(const std::vector<std::filesystem::path>& dirs);

}  // namespace terrasol
