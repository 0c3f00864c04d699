#include "mesh/section_mesh.h"

#include "mesh/section_visibility.h"

namespace terrasol {

SectionMesh meshWithLinks(const SectionSnapshot& snapshot, const BlockMeshTable& table) {
  SectionMesh mesh = meshSection(snapshot, table);
  mesh.faceLinks = sectionFaceLinks(snapshot);
  return mesh;
}

SectionMesh uncapturedMesh(SectionPos pos, CaptureResult why) {
  SectionMesh mesh{pos, {}};
  mesh.faceLinks = why == CaptureResult::Buried ? kNoFacesLinked : kAllFacesLinked;
  return mesh;
}

SectionMesh meshFromWorld(const World& world, SectionPos pos, const BlockMeshTable& table,
                          SectionSnapshot& scratch) {
  const CaptureResult captured = captureSection(world, pos, scratch);
  return captured == CaptureResult::Captured ? meshWithLinks(scratch, table) : uncapturedMesh(pos, captured);
}

}  // namespace terrasol
