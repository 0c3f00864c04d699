#pragma once
// A shader pack's `block.properties`: the number each block state gives `mc_Entity.x`, as OptiFine
// reads the file (shaders.txt "Block ID mapping"): `block.<id>=<block> <block>...`, a block written
// `[minecraft:]name[:property=value[,value]...]...`, conditionals as in every `.properties` file, a
// trailing `\` joining lines. Names are matched against Terrasol's block registry; names it does not
// know (other versions', mods') are counted, not errors. A state named twice keeps the first id, as
// OptiFine does. GL-free.

#include <string>
#include <vector>

#include "shaderpack/pack_conditions.h"
#include "world/block_registry.h"

namespace terrasol {

struct BlockIdMap {
  std::vector<int> ids;              // per state; -1 where the pack names none
  std::vector<std::string> unknown;  // block names nothing in the registry has
  int mappedStates() const;
};

// Throws Error naming `file` and the line for a malformed entry (an id that is not a number, a
// property without a value) or conditional.
BlockIdMap parseBlockProperties(std::string_view text, const std::string& file, PackMacros macros,
                                const BlockRegistry& blocks);

}  // namespace terrasol
