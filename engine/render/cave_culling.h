#pragma once
// Minecraft's cave culling: sections are walked outward from the camera's, entering a section through
// one face and leaving through another only when the section links the two (open cells join them;
// mesh/section_visibility.h), never turning back towards the camera, and only into sections inside the
// frustum. Sections the walk never reaches are hidden behind solid ground however the frustum sees them.

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "render/frustum.h"
#include "render/section_meshes.h"

namespace terrasol {

// A set of sections in the square of `radius` sections around a chunk, the world's height: a byte per
// section, so a lookup is an index (the renderer asks once per section per pass), not a tree walk.
class SectionSet {
 public:
  static constexpr std::uint8_t kMember = 0x80;  // the other bits are the walks' own marks

  SectionSet(glm::ivec2 centreChunk, int radius);
  bool contains(SectionPos s) const {
    const std::uint8_t* c = cell({s.x, s.section, s.z});
    return c && (*c & kMember);
  }
  // The section's byte (section x, index, z); null outside the square.
  std::uint8_t* cell(glm::ivec3 s) { return const_cast<std::uint8_t*>(std::as_const(*this).cell(s)); }
  const std::uint8_t* cell(glm::ivec3 s) const;

 private:
  glm::ivec2 centre_;
  int radius_, side_;
  std::vector<std::uint8_t> cells_;
};

// The reachable sections within `radius` sections (horizontally) of the camera's. `planes` are
// camera-relative, like every box test in the renderer.
SectionSet reachableSections(const SectionMeshes& meshes, glm::dvec3 camera, const FrustumPlanes& planes,
                             int radius);

// The same walk for a directional light shining along -`toLight`: from the sky and from the sides of
// the square of `radius` sections around `centre` that face the light, moving only the ways its rays
// move, through linked faces. The sections it never reaches hold no face its rays can meet first (a
// ray meets its first face after open cells only), so they cast nothing. A section is walked once per
// face it is entered by (rays enter it by different faces), so no ray's path is cut short.
SectionSet sectionsLitFrom(const SectionMeshes& meshes, glm::vec3 toLight, glm::dvec3 centre, int radius);

}  // namespace terrasol
