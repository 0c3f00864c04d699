#pragma once
// The creative inventory's search and groups, as Minecraft's: plain C++, so tests call them without a
// window.

#include <string_view>

#include "core/enum_names.h"
#include "world/block.h"

namespace terrasol {

// Every word of `query` appears in `name`, case ignored, "_" read as a space ("oak st" finds
// "oak_stairs"). An empty query matches everything.
bool matchesSearch(std::string_view name, std::string_view query);

// Minecraft's creative tabs for blocks.
enum class InventoryGroup : std::uint8_t { Building, Coloured, Natural, Functional, Redstone };
inline constexpr EnumNames<InventoryGroup, 5> kInventoryGroups{
    {"Building", "Coloured", "Natural", "Functional", "Redstone"}};

// The tab a block is found in, by its name and shape as Minecraft sorts its blocks: dyed blocks
// coloured; redstone's parts, rails, buttons and plates redstone; work stations, storage, light,
// signs, heads and decorations functional; soils, ores, logs, leaves, plants, coral and ice natural;
// the rest (stones, planks and their shapes, metals, glass) building.
InventoryGroup groupOf(const BlockType& type);

}  // namespace terrasol
