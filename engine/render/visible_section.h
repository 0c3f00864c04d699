#pragma once
// A section with a mesh inside a frustum (the camera's or the light's), as the passes draw it.

#include <glm/vec3.hpp>

#include "render/section_meshes.h"

namespace terrasol {

struct VisibleSection {
  const SectionMeshes::Section* section;
  glm::vec3 offset;  // section corner minus camera
  SectionPos pos;
};

}  // namespace terrasol
