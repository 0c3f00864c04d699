#include "render/prop_draw.h"

#include <algorithm>

namespace terrasol {

PropUniforms::PropUniforms(const LinkedProgram& p, bool lit)
    : modelOffset(p, "u_modelOffset"),
      basis(p, "u_basis"),
      baseColor(p, "u_baseColorFactor"),
      alphaCutoff(p, "u_alphaCutoff") {
  if (!lit) return;
  rotation = {p, "u_rotation"};
  metallic = {p, "u_metallic"};
  roughness = {p, "u_roughness"};
  emissive = {p, "u_emissiveFactor"};
  normalScale = {p, "u_normalScale"};
  occlusion = {p, "u_occlusionStrength"};
  hasNormalMap = {p, "u_hasNormalMap"};
}

std::vector<int> propsInside(const FrustumPlanes& planes, glm::dvec3 camera, const Props& props) {
  std::vector<int> inside;
  const auto& instances = props.instances();
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Props::Placement& p = instances[i].placement;
    if (boxVisible(planes, glm::vec3(p.min - camera), glm::vec3(p.max - camera)))
      inside.push_back(static_cast<int>(i));
  }
  return inside;
}

bool anyBlended(const Props& props, const std::vector<int>& instances) {
  for (const int i : instances) {
    const Props::GpuModel& model =
        props.models()[static_cast<std::size_t>(props.instances()[static_cast<std::size_t>(i)].model)];
    for (const Props::Mesh& mesh : model.meshes) {
      if (model.materials[static_cast<std::size_t>(mesh.material)].params.alphaMode == AlphaMode::Blend)
        return true;
    }
  }
  return false;
}

void drawProps(GLuint program, const PropUniforms& u, const Props& props, const std::vector<int>& instances,
               glm::dvec3 camera, AlphaMode mode, bool cullBackFaces) {
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
    const glm::vec3 offset(p.position - camera);  // in double: far from the origin too
    u.modelOffset.set(offset);
    u.basis.set(p.basis);
    u.rotation.set(p.rotation);
    glBindVertexArray(model.layout.id());
    glVertexArrayVertexBuffer(model.layout.id(), 1, instance.light.id(), 0, sizeof(glm::vec2));
    for (const Props::Mesh& mesh : model.meshes) {
      const Props::Material& material = model.materials[static_cast<std::size_t>(mesh.material)];
      const ModelMaterial& m = material.params;
      if (m.alphaMode != mode || mesh.indexCount == 0) continue;
      props.bindMaterial(material);
      u.baseColor.set(m.baseColor);
      u.metallic.set(m.metallic);
      u.roughness.set(m.roughness);
      u.emissive.set(m.emissive);
      u.normalScale.set(m.normalScale);
      u.occlusion.set(m.occlusionStrength);
      u.alphaCutoff.set(m.alphaCutoff);
      u.hasNormalMap.set(material.hasNormalMap);
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
