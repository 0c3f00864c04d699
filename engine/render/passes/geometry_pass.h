#pragma once
// Opaque, then alpha-tested cutout sections and props into the G-buffer, nearest first.

#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class GeometryPass final : public RenderPass {
 public:
  GeometryPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "geometry"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  PassShared& shared_;
  gl::Program opaque_, cutout_;
  gl::Program propOpaque_, propCutout_;  // each only when a placed prop needs it
};

}  // namespace terrasol
