#pragma once
// The creative inventory's search, as Minecraft's: plain C++, so tests call it without a window.

#include <string_view>

namespace terrasol {

// Every word of `query` appears in `name`, case ignored, "_" read as a space ("oak st" finds
// "oak_stairs"). An empty query matches everything.
bool matchesSearch(std::string_view name, std::string_view query);

}  // namespace terrasol
