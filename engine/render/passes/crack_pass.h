#pragma once
// Minecraft's crack on the block being dug (FrameInputs::crack), multiplied into the G-buffer's
// albedo wherever a surface lies in the block's cell, so the lighting lights it with the block. Its
// ten stages are atlas textures (assets/crack_textures.h); where no pack has them, no crack.

#include <array>
#include <optional>

#include "assets/crack_textures.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class CrackPass final : public RenderPass {
 public:
  CrackPass(const VariantBuilder& build, PassShared& shared, const Atlas& atlas);

  const char* name() const override { return "crack"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Uniforms {
    Uniforms() = default;
    explicit Uniforms(const LinkedProgram& p)
        : viewProjection(p, "u_viewProjection"),
          inverseViewProjection(p, "u_inverseViewProjection"),
          boxMin(p, "u_boxMin"),
          boxMax(p, "u_boxMax"),
          cellMin(p, "u_cellMin"),
          cellMax(p, "u_cellMax"),
          tile(p, "u_tile"),
          viewport(p, "u_viewport") {}
    gl::Uniform<glm::mat4> viewProjection, inverseViewProjection;
    gl::Uniform<glm::vec3> boxMin, boxMax, cellMin, cellMax;
    gl::Uniform<glm::vec4> tile;
    gl::Uniform<glm::vec2> viewport;
  };

  PassShared& shared_;
  gl::ProgramWith<Uniforms> program_;
  std::array<std::optional<glm::vec4>, kCrackStages> tiles_;  // each stage's texels in the atlas
};

}  // namespace terrasol
