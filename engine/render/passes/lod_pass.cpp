#include "render/passes/lod_pass.h"

#include "render/lod_draw.h"

namespace terrasol {

LodPass::LodPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared), program_(build("lod.vert", "lod.frag", shared.contents.defines())) {}

void LodPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!frame.inputs.lod || frame.inputs.lod->empty()) return builder.skip("no far terrain");
  builder.read(frame.resources.gbuffer);
  builder.write(frame.resources.gbuffer);
}

void LodPass::execute(Frame& frame) {
  bindForOpaqueGeometry(*frame.gbuffer);
  const FrameView& view = frame.view;
  glUseProgram(program_.id());
  program_.u.viewProjection.set(view.viewProjection);
  const LodDrawCounts counts =
      drawLodTiles(*frame.inputs.lod, view.frustum, view.camera, program_.u.tile, true);
  frame.stats.lodTilesDrawn += counts.drawn;
  frame.stats.lodTilesCulled += counts.culled;
  frame.stats.lodTrianglesDrawn += counts.triangles;
}

}  // namespace terrasol
