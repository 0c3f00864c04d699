#pragma once
// Far terrain into the G-buffer after the near terrain, so it takes the same lighting, sky light, fog,
// shadows and reflections. Full detail hides it: the cells it covers sink to the world's floor in the
// vertex shader, under the ground full detail draws there.

#include "render/lod_draw.h"
#include "render/lod_meshes.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class LodPass final : public RenderPass {
 public:
  LodPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "lod"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Uniforms {
    Uniforms() = default;
    explicit Uniforms(const LinkedProgram& p) : viewProjection(p, "u_viewProjection"), tile(p) {}
    gl::Uniform<glm::mat4> viewProjection;
    LodTileUniforms tile;
  };

  PassShared& shared_;
  gl::ProgramWith<Uniforms> program_;
};

}  // namespace terrasol
