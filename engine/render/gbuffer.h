#pragma once
// The G-buffer targets (layout in gbuffer_layout.h) and the HDR scene target the lighting and
// translucent passes write, sized together. GL thread only.

#include <array>
#include <glm/gtc/type_precision.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "render/gbuffer_layout.h"
#include "render/gl/object.h"

namespace terrasol {

// The targets read back to the CPU, rows bottom first as GL stores them (pixel (x, y) at y * width + x).
struct GBufferPixels {
  glm::ivec2 size{0};
  std::vector<float> depth;        // 0..1, 1 = sky
  std::vector<glm::vec4> normals;  // octahedral surface xy, vertex zw (vertex xy without surface normals)
  std::vector<glm::vec4> scene;    // linear HDR; alpha = the direct light's shadow term (lighting.glsl)
  std::vector<glm::u8vec4> light;  // block, sky, vertex AO
};

class GBuffer {
 public:
  // Throws Error for a non-positive size or an incomplete framebuffer.
  explicit GBuffer(glm::ivec2 size, GBufferContents contents = {});

  glm::ivec2 size() const { return size_; }
  const GBufferContents& contents() const { return contents_; }
  GLuint target(int index) const { return targets_[static_cast<std::size_t>(index)].id(); }
  GLuint depth() const { return depth_.id(); }
  GLuint scene() const { return scene_.id(); }  // RGBA16F, linear HDR
  // The copy of depth the lighting pass tests against (copyDepthForLighting); never attached while the
  // translucent pass draws, so it may sample it.
  GLuint lightingDepth() const { return lightingDepth_.id(); }

  GLuint geometryFramebuffer() const { return geometry_.id(); }  // every target + depth
  // The albedo target alone, for decals that read depth and normals while they change albedo.
  GLuint decalFramebuffer() const { return decal_.id(); }
  // The scene, with a copy of depth (copyDepthForLighting) that the lighting and sky draws are tested
  // against: each runs only on its own pixels. The lighting shader samples the original, so no texture
  // it reads is attached.
  GLuint lightingFramebuffer() const { return lighting_.id(); }
  // The scene + depth, tested not written; and at slots::kOutReactive the reactive mask, drawn only
  // when the translucent pass selects its draw buffer.
  GLuint translucentFramebuffer() const { return translucent_.id(); }
  GLuint reactive() const { return reactive_.id(); }  // R8: 1 where TAA's history should count less

  // The depth the geometry pass wrote, into the lighting framebuffer's copy.
  void copyDepthForLighting() const;
  // Binds the targets and depth to the texture units gbuffer_layout.h names.
  void bindForReading() const;
  // Reads depth, normals, light and the lit scene back (slow: for tests and reports).
  GBufferPixels read() const;

 private:
  glm::ivec2 size_;
  GBufferContents contents_;
  std::array<gl::Texture, gbuffer::kTargets> targets_;
  gl::Texture depth_, lightingDepth_, scene_, reactive_;
  gl::Framebuffer geometry_, lighting_, translucent_, decal_;
};

}  // namespace terrasol
