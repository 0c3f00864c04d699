#pragma once
// Far terrain into the G-buffer after the near terrain, so it takes the same lighting, sky light, fog,
// shadows and reflections. Full detail hides it: the cells it covers sink to the world's floor in the
// vertex shader, under the ground full detail draws there.

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
    explicit Uniforms(const LinkedProgram& p)
        : viewProjection(p, "u_viewProjection"),
          tileOffset(p, "u_tileOffset"),
          cellBlocks(p, "u_cellBlocks"),
          maskOffset(p, "u_maskOffset"),
          masked(p, "u_masked") {}
    gl::Uniform<glm::mat4> viewProjection;
    gl::Uniform<glm::vec3> tileOffset;  // the tile's minimum corner at y 0, from the camera
    gl::Uniform<int> cellBlocks;
    gl::Uniform<glm::ivec2> maskOffset;  // the tile's minimum corner, in blocks from the mask's
    gl::Uniform<bool> masked;            // the tile reaches into full detail
  };

  PassShared& shared_;
  gl::ProgramWith<Uniforms> program_;
};

}  // namespace terrasol
