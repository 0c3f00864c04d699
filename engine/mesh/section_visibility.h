#pragma once
// Minecraft's cave-culling graph, per section: which pairs of the section's six faces are joined by a
// path of cells that are not opaque cubes. The renderer walks sections outward from the camera and only
// passes through a section from one face to another when this says light (and sight) could.

#include <cstdint>

#include "mesh/mesh_data.h"
#include "mesh/section_snapshot.h"

namespace terrasol {

// Flood fill over the section's 16³ cells (not the halo).
FaceLinks sectionFaceLinks(const SectionSnapshot& snapshot);

}  // namespace terrasol
