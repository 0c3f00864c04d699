#pragma once
// Opaque, then alpha-tested cutout sections and props into the G-buffer, nearest first.

#include "render/pass_shared.h"
#include "render/prop_draw.h"
#include "render/render_pass.h"
#include "render/section_draw.h"

namespace terrasol {

class GeometryPass final : public RenderPass {
 public:
  GeometryPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "geometry"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Blocks {
    Blocks() = default;
    explicit Blocks(const LinkedProgram& p)
        : section(p),
          viewProjection(p, "u_viewProjection"),
          viewportPixels(p, "u_viewportPixels"),
          sealMergedEdges(p, "u_sealMergedEdges") {}
    SectionUniforms section;
    gl::Uniform<glm::mat4> viewProjection;
    gl::Uniform<glm::vec2> viewportPixels;
    gl::Uniform<bool> sealMergedEdges;
  };
  struct Prop {
    Prop() = default;
    explicit Prop(const LinkedProgram& p) : prop(p, true), viewProjection(p, "u_viewProjection") {}
    PropUniforms prop;
    gl::Uniform<glm::mat4> viewProjection;
  };

  PassShared& shared_;
  gl::ProgramWith<Blocks> opaque_, cutout_;
  gl::ProgramWith<Prop> propOpaque_, propCutout_;  // each only when a placed prop needs it
};

}  // namespace terrasol
