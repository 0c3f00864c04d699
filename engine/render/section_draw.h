#pragma once
// Drawing sections' meshes, shared by the geometry, translucent and shadow passes.

#include <glm/vec3.hpp>
#include <vector>

#include "render/block_textures.h"
#include "render/frame_inputs.h"
#include "render/frustum.h"
#include "render/section_meshes.h"
#include "render/visible_section.h"

namespace terrasol {

// The sections with a mesh whose box is inside `planes` (camera-relative); counts the others.
std::vector<VisibleSection> sectionsInside(const FrustumPlanes& planes, glm::dvec3 camera,
                                           const SectionMeshes& meshes, int* outside = nullptr);

// The uniforms drawSections sets in a block program: the atlas grid and each section's offset.
struct SectionUniforms {
  SectionUniforms() = default;
  explicit SectionUniforms(const LinkedProgram& p) : atlas(p), offset(p, "u_sectionOffset") {}

  AtlasUniforms atlas;
  gl::Uniform<glm::vec3> offset;
};

// How drawSections orders and trims: sections by their centre's distance from the camera, or (with a
// non-zero `axis`) by how far along `axis` it lies, nearest first so the depth test can reject hidden
// fragments before shading. `cullFacesAway` (passes that cull back faces) leaves out face groups
// turned away from the camera for a whole section before any vertex is shaded; with `stats` what is
// drawn and left out is counted (the camera's passes).
enum class DrawOrder { NearestFirst, FarthestFirst };
struct SectionDraw {
  DrawOrder order = DrawOrder::NearestFirst;
  glm::vec3 axis{0.0f};
  bool cullFacesAway = false;
  FrameStats* stats = nullptr;
  SectionMeshes::View view = SectionMeshes::View::Camera;
};

void drawSections(GLuint program, const SectionUniforms& uniforms, const BlockTextures& textures,
                  const std::vector<VisibleSection>& sections, const SectionMeshes& meshes, MeshLayer layer,
                  const SectionDraw& how);

// The quads of `layer` in `sections`.
std::size_t quadsIn(const std::vector<VisibleSection>& sections, MeshLayer layer);

}  // namespace terrasol
