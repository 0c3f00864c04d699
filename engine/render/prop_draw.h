#pragma once
// Props in the renderer's passes: culled by their world box, drawn mesh by mesh with their material's
// uniforms and textures (render/props.h), in the G-buffer, translucent and shadow passes.

#include <glm/vec3.hpp>
#include <vector>

#include "render/frustum.h"
#include "render/gl/uniforms.h"
#include "render/props.h"

namespace terrasol {

// The uniforms drawProps sets: each instance's placement and each mesh's material. The shadow
// programs (`lit` false) read the placement without normals and only what alpha needs.
struct PropUniforms {
  PropUniforms() = default;
  PropUniforms(const LinkedProgram& p, bool lit);

  gl::Uniform<glm::vec3> modelOffset;
  gl::Uniform<glm::mat3> basis, rotation;
  gl::Uniform<glm::vec4> baseColor;
  gl::Uniform<float> metallic, roughness;
  gl::Uniform<glm::vec3> emissive;
  gl::Uniform<float> normalScale, occlusion, alphaCutoff;
  gl::Uniform<bool> hasNormalMap;
};

// The instances whose box is inside `planes` (relative to `camera`).
std::vector<int> propsInside(const FrustumPlanes& planes, glm::dvec3 camera, const Props& props);
// Whether a mesh of `instances` has a blended material (the translucent pass draws those).
bool anyBlended(const Props& props, const std::vector<int>& instances);
// The meshes of `instances` whose material has alpha mode `mode` (blended ones farthest first).
void drawProps(GLuint program, const PropUniforms& u, const Props& props, const std::vector<int>& instances,
               glm::dvec3 camera, AlphaMode mode, bool cullBackFaces);

}  // namespace terrasol
