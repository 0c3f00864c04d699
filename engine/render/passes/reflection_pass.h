#pragma once
// Screen-space reflections of smooth opaque and cutout surfaces (shaders/reflection.frag), added to
// the lit scene before the translucent pass. Three draws into a target of its own, at
// render.reflections.resolution_scale of the frame: a mask (depth 0 where a surface is smooth enough),
// the march (only there, by the depth test), then the result filtered up and added to the scene
// where something was drawn. Has nothing to do when reflections are off, or no loaded texture, or
// no texture of the sections in view, is smooth enough.

#include <glm/vec4.hpp>
#include <vector>

#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

// The last march read back (slow: for the reflection-error report), at the pass's own resolution,
// rows bottom first.
struct ReflectionPixels {
  glm::ivec2 size{0};
  std::vector<glm::vec4> added;  // rgb added to the lit scene; a: 1 where the ray hit
  std::vector<glm::vec4> hits;   // xy: hit screen uv; z: 1 hit, 0 marched without a hit, -1 not marched
};

class ReflectionPass final : public RenderPass {
 public:
  ReflectionPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "reflection"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

  ReflectionPixels read() const;

 private:
  bool smoothInView(const Frame& frame) const;
  void ensureTarget(glm::ivec2 size);
  void setMarchUniforms(const Frame& frame) const;

  PassShared& shared_;
  gl::Program mask_, march_, composite_;  // only when reflections are on
  glm::ivec2 size_{0};
  gl::Texture colour_;  // RGBA16F: rgb added to the scene, a: 1 where the ray hit something on screen
  gl::Texture hits_;    // RGBA32F: where each ray hit (ReflectionPixels::hits)
  gl::Renderbuffer depth_;
  gl::Framebuffer target_;
};

}  // namespace terrasol
