#pragma once
// Blocks a resource pack adds: a blockstates file (assets/minecraft/blockstates/<name>.json) for a
// name the registry does not know becomes a block, so a newer Minecraft's or a pack's own blocks draw
// instead of vanishing. Its properties and values are those its variants' keys and its parts'
// conditions name, each value in the order it first appears (variants taken by key, as the JSON reader
// orders them); its default state the first variant's; it stops light and hides its neighbours'
// faces when its default state's models fill the cell, and is drawn cut out otherwise.

#include <string>
#include <vector>

#include "assets/resource_pack.h"
#include "assets/texture_loader.h"
#include "world/block_registry.h"

namespace terrasol {

// The blocks `packs` add to `blocks`, sorted by name. A blockstates file that cannot be read is left
// out, the reason among `problems`.
std::vector<BlockType> packBlockTypes(const BlockRegistry& blocks, const PackStack& packs,
                                      std::vector<PackProblem>& problems);

// `blocks` with the blocks `packs` add appended (BlockRegistry::addPackBlocks).
BlockRegistry withPackBlocks(BlockRegistry blocks, const PackStack& packs,
                             std::vector<PackProblem>& problems);

}  // namespace terrasol
