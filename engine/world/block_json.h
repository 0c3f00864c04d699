#pragma once
// One block's entry in a pack's blocks.json (resourcepacks/default/blocks.json): how it looks and the
// rules the game gives it, and, for a block Minecraft's table does not know, its states and light.
// Errors name the key path ("blocks[3] (oak_log).properties.axis"); the registry adds the file.

#include <string>

#include "core/json_check.h"
#include "world/block.h"

namespace terrasol {

// "properties" and "default": the block's states; type.defaultState is relative to its first state.
void parseStates(const json_check::json& block, BlockType& type, const std::string& at);

// "hardness": Minecraft's digging measure, kUnbreakable (-1) or from 0 up.
float parseHardness(const json_check::json& value, const std::string& key);

// A block the pack adds: everything from its entry. `where` is its place: "blocks[3]".
BlockType parsePackBlock(const json_check::json& block, const std::string& where);

// A block of Minecraft's table: its looks and rules from the entry (shape, layer, textures, tint,
// placement, connects, opens, wall_variant are read later); the facts the table gives (states, light,
// collision) are refused there.
void parseLooksAndRules(const json_check::json& block, BlockType& type, const std::string& where);

}  // namespace terrasol
