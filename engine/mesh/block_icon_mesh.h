#pragma once
// What an inventory icon draws: one block state alone in open daylight, meshed as the world meshes
// it, and which blocks get an icon. Plain C++; render/block_icons.h draws these.

#include <span>
#include <string>
#include <vector>

#include "mesh/mesher.h"

namespace terrasol {

// The block sits in cell kIconCell of its section (room on every side for parts that stick out).
inline constexpr int kIconCell = 7;

// The state's quads, lit by full sky light from every side, tinted as in the plains.
SectionMesh iconMesh(const BlockMeshTable& table, const BlockRegistry& blocks, BlockId state);

// A state of every block a player can pick, in registry order: not air, nothing without a shape, no
// block that only stands in for another when placed against a wall (a wall torch), and none of the
// `placeholders` (blocks no pack draws: BlockAtlas::placeholders). The default state, but fences,
// panes and walls joined east and west.
std::vector<BlockId> iconStates(const BlockRegistry& blocks, std::span<const std::string> placeholders);

}  // namespace terrasol
