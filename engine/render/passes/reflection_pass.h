#pragma once
// Screen-space reflections of smooth opaque and cutout surfaces (shaders/reflection.frag), added to
// the lit scene before the translucent pass. Three draws into a target of its own, at
// render.reflections.resolution_scale of the frame: a mask (depth 0 where a surface is smooth enough),
// the march (only there, by the depth test), then the result filtered up and added to the scene
// where something was drawn. Has nothing to do when reflections are off or no loaded texture is
// smooth enough.

#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class ReflectionPass final : public RenderPass {
 public:
  ReflectionPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "reflection"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  void ensureTarget(glm::ivec2 size);
  void setMarchUniforms(const Frame& frame) const;

  PassShared& shared_;
  gl::Program mask_, march_, composite_;  // only when reflections are on
  glm::ivec2 size_{0};
  gl::Texture colour_;  // RGBA16F: rgb added to the scene, a: 1 where the ray hit something on screen
  gl::Renderbuffer depth_;
  gl::Framebuffer target_;
};

}  // namespace terrasol
