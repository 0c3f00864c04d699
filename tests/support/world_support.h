#pragma once
// Shared bits for world tests: the shipped block table and fresh scratch directories.

#include <filesystem>
#include <string>

#include "world/block_registry.h"
#include "world/block_shapes.h"
#include "world/chunk.h"

namespace terrasol::testing {

// build/test-output, created on demand.
std::filesystem::path testOutputDir();
// resourcepacks/default/blocks.json, loaded once per process.
const BlockRegistry& defaultBlocks();
// Shapes for defaultBlocks() written out by hand, for tests that cannot read models: cubes, the
// slabs, and straight stairs, boxed as the default pack's models box them (a CPU test checks that);
// other model blocks have none.
const BlockShapes& handShapes();
// build/test-output/<name>, emptied.
std::filesystem::path scratchDir(const std::string& name);
// True when both chunks hold the same blocks everywhere.
bool sameBlocks(const Chunk& a, const Chunk& b);

}  // namespace terrasol::testing
