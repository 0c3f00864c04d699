#include <algorithm>

#include "render/deferred_renderer.h"
#include "render/gl/uniforms.h"

// The deferred renderer's props: culled by their world box, drawn mesh by mesh with their material's
// uniforms and textures (engine/render/props.h), in the G-buffer, translucent and shadow passes.

namespace terrasol {

using gl::setFloat;
using gl::setMat3;
using gl::setVec3;
using gl::setVec4;

std::vector<int> DeferredRenderer::propsInside(const FrustumPlanes& planes, glm::dvec3 camera, const Props& props) {
  std::vector<int> inside;
  const auto& instances = props.instances();
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Props::Placement& p = instances[i].placement;
    if (boxVisible(planes, glm::vec3(p.min - camera), glm::vec3(p.max - camera))) inside.push_back(static_cast<int>(i));
  }
  return inside;
}

bool DeferredRenderer::visibleBlendedProps() const {
  if (!props_ || !propTranslucent_.id()) return false;
  for (const int i : visibleProps_) {
    const Props::GpuModel& model = props_->models()[static_cast<std::size_t>(props_->instances()[static_cast<std::size_t>(i)].model)];
    for (const Props::Mesh& mesh : model.meshes) {
      if (model.materials[static_cast<std::size_t>(mesh.material)].params.alphaMode == AlphaMode::Blend) return true;
    }
  }
  return false;
}

void DeferredRenderer::drawProps(GLuint program, const Props& props, const std::vector<int>& instances,
                                 glm::dvec3 camera, AlphaMode mode, bool cullBackFaces) const {
  std::vector<int> order = instances;
  if (mode == AlphaMode::Blend) {  // farthest first, by the centre of their box
    auto distance = [&](int i) {
      const Props::Placement& p = props.instances()[static_cast<std::size_t>(i)].placement;
      return glm::length(0.5 * (p.min + p.max) - camera);
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return distance(a) > distance(b); });
  }
  glUseProgram(program);
  for (const int i : order) {
    const Props::Instance& instance = props.instances()[static_cast<std::size_t>(i)];
    const Props::GpuModel& model = props.models()[static_cast<std::size_t>(instance.model)];
    const Props::Placement& p = instance.placement;
    setVec3(program, "u_modelOffset", glm::vec3(p.position - camera));  // in double: far from the origin too
    setMat3(program, "u_basis", p.basis);
    setMat3(program, "u_rotation", p.rotation);
    glBindVertexArray(model.layout.id());
    glVertexArrayVertexBuffer(model.layout.id(), 1, instance.light.id(), 0, sizeof(glm::vec2));
    for (const Props::Mesh& mesh : model.meshes) {
      const Props::Material& material = model.materials[static_cast<std::size_t>(mesh.material)];
      const ModelMaterial& m = material.params;
      if (m.alphaMode != mode || mesh.indexCount == 0) continue;
      props.bindMaterial(material);
      setVec4(program, "u_baseColorFactor", m.baseColor);
      setFloat(program, "u_metallic", m.metallic);
      setFloat(program, "u_roughness", m.roughness);
      setVec3(program, "u_emissiveFactor", m.emissive);
      setFloat(program, "u_normalScale", m.normalScale);
      setFloat(program, "u_occlusionStrength", m.occlusionStrength);
      setFloat(program, "u_alphaCutoff", m.alphaCutoff);
      glProgramUniform1i(program, glGetUniformLocation(program, "u_hasNormalMap"), material.hasNormalMap ? 1 : 0);
      if (cullBackFaces && !m.doubleSided) {
        glEnable(GL_CULL_FACE);
      } else {
        glDisable(GL_CULL_FACE);
      }
      glDrawElementsBaseVertex(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT,
                               reinterpret_cast<const void*>(mesh.indexOffset), mesh.baseVertex);
    }
  }
  glBindVertexArray(0);
  if (cullBackFaces) glEnable(GL_CULL_FACE);
}

}  // namespace terrasol
