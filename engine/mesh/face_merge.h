#pragma once
// Greedy merging of full-block faces into larger quads. llvmpipe shades whole 4x4-pixel blocks, and a
// block face a few pixels across covers a fraction of the blocks it touches, so the same picture drawn
// with fewer, larger quads runs the fragment shader far fewer times.
//
// Faces merge when they lie in one plane and carry the same material (texture, face, tint) and the
// same light (block, sky, ambient occlusion) at all four corners: nothing the merged quad interpolates
// varied across the faces it replaces. The merged quad's UV runs 0..w and 0..h textures across, in
// the same direction as the faces' own, and the shaders repeat the texture (lib/atlas_uv.glsl), so
// every texel lands where it did. Other quads pass through untouched.

#include "mesh/mesh_data.h"

namespace terrasol {

// Merges the faces among `quads` (4 vertices each, as the mesher writes them). Afterwards `quads` holds
// the quads that did not merge (QuadRole::Both), the faces that did (Faces: the light's view draws
// them) and the merged quads (Merged: the camera's view), in that order; returns how many faces merged.
std::size_t mergeFaces(PackedVertices& quads);

}  // namespace terrasol
