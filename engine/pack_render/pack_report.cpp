// PackRenderer::readReport: the last frame of a pack that names its shadow term and normal, read back
// as the shadow report reads Terrasol's G-buffer.

#include "core/octahedral.h"
#include "pack_render/pack_renderer.h"

namespace terrasol {

std::optional<GBufferPixels> PackRenderer::readReport() const {
  if (!targets_ || !reportShadow_ || !reportNormal_) return std::nullopt;
  const glm::ivec2 size = targets_->size();
  const auto count = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  GBufferPixels out;
  out.size = size;
  out.depth.resize(count);
  glGetTextureImage(targets_->depth(1), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(count * sizeof(float)), out.depth.data());
  std::vector<glm::vec4> shadow(count), normal(count);
  glGetTextureImage(targets_->main(*reportShadow_), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(count * sizeof(glm::vec4)), shadow.data());
  glGetTextureImage(targets_->main(*reportNormal_), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(count * sizeof(glm::vec4)), normal.data());
  const glm::mat3 toWorld = glm::inverse(glm::mat3(lastModelView_));
  out.normals.resize(count);
  out.scene.resize(count);
  // The pack's light levels are its own: no sky light to count cave leaks by.
  out.light.assign(count, glm::u8vec4(0, 255, 0, 0));
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 view = glm::vec3(normal[i]) * 2.0f - 1.0f;
    const float length = glm::length(view);
    const glm::dvec3 world =
        length > 1e-6f ? glm::dvec3(toWorld * (view / length)) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec2 oct = octEncode(world);
    out.normals[i] = glm::vec4(0.0f, 0.0f, static_cast<float>(oct.x), static_cast<float>(oct.y));
    out.scene[i] = glm::vec4(0.0f, 0.0f, 0.0f, shadow[i].r);
  }
  return out;
}

}  // namespace terrasol
