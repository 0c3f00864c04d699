#pragma once
// The passes that draw into the frame's target framebuffer: the final image (exposure, tone map,
// sRGB), a debug view of a G-buffer channel instead of it, and the targeted block's outline over
// either.

#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class FinalPass final : public RenderPass {
 public:
  FinalPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "final"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  PassShared& shared_;
  gl::Program final_, upscale_;
  // At a render scale: the final image at the scene's size, then scaled up to the target.
  glm::ivec2 imageSize_{0};
  gl::Texture image_;
  gl::Framebuffer imageTarget_;
};

// Writes the target without reading the lit scene, so the graph leaves out what only the final image needs.
class DebugViewPass final : public RenderPass {
 public:
  DebugViewPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "debug_view"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  PassShared& shared_;
  gl::Program debug_;
};

// Edges of FrameInputs::outline, hidden where the G-buffer's depth has something nearer.
class OutlinePass final : public RenderPass {
 public:
  OutlinePass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "outline"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  PassShared& shared_;
  gl::Program outline_;
};

}  // namespace terrasol
