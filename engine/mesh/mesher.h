#pragma once
// Meshing a section snapshot into quads, as a pure function (any thread).
//
// Cube faces are emitted where the neighbour is not an opaque cube; translucent blocks and clear
// cubes (glass) also hide faces against the same block (water-water, glass-glass), while leaves show
// their inner faces, as Minecraft's fancy leaves do. Liquid surfaces sit 2/16 below the block top
// unless the same liquid is above; a waterlogged cell draws its block and water. Cross plants are two
// double-sided diagonal planes, torches a small box with Minecraft's torch UVs.
//
// Smooth lighting as vanilla's: each corner of a face averages block and sky light over the four
// cells in front of it (the front cell, the two beside it towards the corner, and the diagonal one),
// leaving out opaque cells, and the diagonal one too when both sides are opaque. Ambient occlusion per
// corner: side1 && side2 ? 0 : 3 - (side1 + side2 + corner). Quads are split along the diagonal whose
// corners are the brighter pair (the anisotropy fix).

#include "mesh/block_mesh_table.h"
#include "mesh/mesh_data.h"
#include "mesh/section_snapshot.h"

namespace terrasol {

SectionMesh meshSection(const SectionSnapshot& snapshot, const BlockMeshTable& table);

}  // namespace terrasol
