#pragma once
// The snapshot -> mesh stage every user of meshes shares (the mesh workers, a scene's world, the
// exporter): a captured section's quads with its cave-culling face links, and the empty mesh of a
// section with no visible face, whose links say why.

#include "mesh/mesher.h"
#include "mesh/section_snapshot.h"

namespace terrasol {

// The quads of a captured snapshot and its face links (section_visibility.h).
SectionMesh meshWithLinks(const SectionSnapshot& snapshot, const BlockMeshTable& table);
// No faces: all air (every face sees every other) or buried (no face sees another).
SectionMesh uncapturedMesh(SectionPos pos, CaptureResult why);
// Both on the calling thread, straight from the world; `scratch` is reused between calls.
SectionMesh meshFromWorld(const World& world, SectionPos pos, const BlockMeshTable& table,
                          SectionSnapshot& scratch);

}  // namespace terrasol
