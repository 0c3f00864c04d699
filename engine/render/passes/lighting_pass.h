#pragma once
// The lit scene: LabPBR lighting where the geometry pass drew something, the sky elsewhere, into the
// HDR scene target. Both draw a full-screen triangle at depth 1 against a copy of the scene's depth,
// so a CPU rasterizer's early depth test skips the other's pixels, block by block, before shading.

#include "render/frame_uniforms.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class LightingPass final : public RenderPass {
 public:
  LightingPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "lighting"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Lighting {
    Lighting() = default;
    explicit Lighting(const LinkedProgram& p) : lit(p), inverseViewProjection(p, "u_inverseViewProjection") {}
    LitUniforms lit;
    gl::Uniform<glm::mat4> inverseViewProjection;
  };
  struct Sky {
    Sky() = default;
    explicit Sky(const LinkedProgram& p) : sky(p), inverseViewProjection(p, "u_inverseViewProjection") {}
    SkyUniforms sky;
    gl::Uniform<glm::mat4> inverseViewProjection;
  };

  PassShared& shared_;
  gl::ProgramWith<Lighting> lighting_;
  gl::ProgramWith<Sky> sky_;
};

}  // namespace terrasol
