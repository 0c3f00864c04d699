#pragma once
// Smooth light on a model block's partial faces, as vanilla interpolates it: the light fields of the
// full face's four corners (PackedVertex::light) weighted by where each vertex of the quad sits on
// that face. Internal to engine/mesh.

#include <cstdint>

#include "mesh/block_mesh_table.h"

namespace terrasol {

// `corner`: the full face's corner fields in the mesher's corner order, for the quad's face. Averages
// and occlusion are interpolated, the block's own shape darkens the corners it fills beside
// (ModelQuad::ownOcclusion), and each vertex's field is stored back as sums over ao + 1 cells.
void interpolateModelLight(const ModelQuad& m, const std::uint32_t (&corner)[4], std::uint32_t (&light)[4]);

}  // namespace terrasol
