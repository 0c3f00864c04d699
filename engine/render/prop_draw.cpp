#include "render/prop_draw.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

namespace terrasol {

namespace {

// A program's prop uniforms, looked up once per draw call rather than once per mesh; -1 where the
// program has no such uniform (the shadow programs read few), which GL ignores.
struct PropUniforms {
  explicit PropUniforms(GLuint p)
      : modelOffset(glGetUniformLocation(p, "u_modelOffset")),
        basis(glGetUniformLocation(p, "u_basis")),
        rotation(glGetUniformLocation(p, "u_rotation")),
        baseColor(glGetUniformLocation(p, "u_baseColorFactor")),
        metallic(glGetUniformLocation(p, "u_metallic")),
        roughness(glGetUniformLocation(p, "u_roughness")),
        emissive(glGetUniformLocation(p, "u_emissiveFactor")),
        normalScale(glGetUniformLocation(p, "u_normalScale")),
        occlusion(glGetUniformLocation(p, "u_occlusionStrength")),
        alphaCutoff(glGetUniformLocation(p, "u_alphaCutoff")),
        hasNormalMap(glGetUniformLocation(p, "u_hasNormalMap")) {}
  GLint modelOffset, basis, rotation, baseColor, metallic, roughness, emissive, normalScale, occlusion, alphaCutoff,
      hasNormalMap;
};

}  // namespace

std::vector<int> propsInside(const FrustumPlanes& planes, glm::dvec3 camera, const Props& props) {
  std::vector<int> inside;
  const auto& instances = props.instances();
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Props::Placement& p = instances[i].placement;
    if (boxVisible(planes, glm::vec3(p.min - camera), glm::vec3(p.max - camera))) inside.push_back(static_cast<int>(i));
  }
  return inside;
}

bool anyBlended(const Props& props, const std::vector<int>& instances) {
  for (const int i : instances) {
    const Props::GpuModel& model = props.models()[static_cast<std::size_t>(props.instances()[static_cast<std::size_t>(i)].model)];
    for (const Props::Mesh& mesh : model.meshes) {
      if (model.materials[static_cast<std::size_t>(mesh.material)].params.alphaMode == AlphaMode::Blend) return true;
    }
  }
  return false;
}

void drawProps(GLuint program, const Props& props, const std::vector<int>& instances, glm::dvec3 camera,
               AlphaMode mode, bool cullBackFaces) {
  std::vector<int> order = instances;
  if (mode == AlphaMode::Blend) {  // farthest first, by the centre of their box
    auto distance = [&](int i) {
      const Props::Placement& p = props.instances()[static_cast<std::size_t>(i)].placement;
      return glm::length(0.5 * (p.min + p.max) - camera);
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return distance(a) > distance(b); });
  }
  glUseProgram(program);
  const PropUniforms u(program);
  for (const int i : order) {
    const Props::Instance& instance = props.instances()[static_cast<std::size_t>(i)];
    const Props::GpuModel& model = props.models()[static_cast<std::size_t>(instance.model)];
    const Props::Placement& p = instance.placement;
    const glm::vec3 offset(p.position - camera);  // in double: far from the origin too
    glProgramUniform3fv(program, u.modelOffset, 1, glm::value_ptr(offset));
    glProgramUniformMatrix3fv(program, u.basis, 1, GL_FALSE, glm::value_ptr(p.basis));
    glProgramUniformMatrix3fv(program, u.rotation, 1, GL_FALSE, glm::value_ptr(p.rotation));
    glBindVertexArray(model.layout.id());
    glVertexArrayVertexBuffer(model.layout.id(), 1, instance.light.id(), 0, sizeof(glm::vec2));
    for (const Props::Mesh& mesh : model.meshes) {
      const Props::Material& material = model.materials[static_cast<std::size_t>(mesh.material)];
      const ModelMaterial& m = material.params;
      if (m.alphaMode != mode || mesh.indexCount == 0) continue;
      props.bindMaterial(material);
      glProgramUniform4fv(program, u.baseColor, 1, glm::value_ptr(m.baseColor));
      glProgramUniform1f(program, u.metallic, m.metallic);
      glProgramUniform1f(program, u.roughness, m.roughness);
      glProgramUniform3fv(program, u.emissive, 1, glm::value_ptr(m.emissive));
      glProgramUniform1f(program, u.normalScale, m.normalScale);
      glProgramUniform1f(program, u.occlusion, m.occlusionStrength);
      glProgramUniform1f(program, u.alphaCutoff, m.alphaCutoff);
      glProgramUniform1i(program, u.hasNormalMap, material.hasNormalMap ? 1 : 0);
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
