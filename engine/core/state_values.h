#pragma once
// A block state's property values by name, as Minecraft writes them: {"facing": "east", "half": "top"}.
// Shared by the block registry (world) and the blockstates files that pick models (assets).

#include <map>
#include <string>

namespace terrasol {

using StateValues = std::map<std::string, std::string>;

}  // namespace terrasol
