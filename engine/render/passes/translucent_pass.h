#pragma once
// Water, glass and blended props, lit forward and blended over the lit scene, farthest first; tested
// against the opaque scene's depth, never hiding each other. Has nothing to do without translucent
// geometry in view.

#include "render/frame_uniforms.h"
#include "render/pass_shared.h"
#include "render/prop_draw.h"
#include "render/render_pass.h"
#include "render/section_draw.h"

namespace terrasol {

class TranslucentPass final : public RenderPass {
 public:
  TranslucentPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "translucent"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  void prepareReflections(const Frame& frame);
  void markReactive(Frame& frame) const;
  struct Blocks {
    Blocks() = default;
    explicit Blocks(const LinkedProgram& p)
        : section(p),
          lit(p),
          waves(p),
          viewProjection(p, "u_viewProjection"),
          nearFar(p, "u_nearFar"),
          minSmoothness(p, "u_minSmoothness"),
          marched(p, "u_marched") {}
    SectionUniforms section;
    LitUniforms lit;
    WaveUniforms waves;
    gl::Uniform<glm::mat4> viewProjection;
    gl::Uniform<glm::vec2> nearFar;  // with reflections
    gl::Uniform<float> minSmoothness;
    gl::Uniform<bool> marched;
  };
  struct Prop {
    Prop() = default;
    explicit Prop(const LinkedProgram& p) : prop(p, true), lit(p), viewProjection(p, "u_viewProjection") {}
    PropUniforms prop;
    LitUniforms lit;
    gl::Uniform<glm::mat4> viewProjection;
  };

  PassShared& shared_;
  gl::ProgramWith<Blocks> blocks_;
  gl::ProgramWith<Prop> props_;  // only when a placed prop has a blended material
  // With reflections: the lit opaque scene copied before blending over it, for the reflected rays.
  glm::ivec2 copySize_{0};
  gl::Texture sceneCopy_;
};

}  // namespace terrasol
