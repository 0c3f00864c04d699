#pragma once
// Water, glass and blended props, lit forward and blended over the lit scene, farthest first; tested
// against the opaque scene's depth, never hiding each other. Has nothing to do without translucent
// geometry in view.

#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class TranslucentPass final : public RenderPass {
 public:
  TranslucentPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "translucent"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  void prepareReflections(const Frame& frame);
  PassShared& shared_;
  gl::Program blocks_;
  gl::Program props_;  // only when a placed prop has a blended material
  // With reflections: the lit opaque scene copied before blending over it, for the reflected rays.
  glm::ivec2 copySize_{0};
  gl::Texture sceneCopy_;
};

}  // namespace terrasol
