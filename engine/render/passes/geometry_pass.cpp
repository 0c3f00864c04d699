#include "render/passes/geometry_pass.h"

namespace terrasol {

GeometryPass::GeometryPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      opaque_(build("gbuffer.vert", "gbuffer.frag", shared.contents.defines())),
      cutout_(build("gbuffer.vert", "gbuffer.frag", with({{"CUTOUT", "1"}}, shared.contents.defines()))) {
  const PropNeeds& needs = shared.options.props;
  if (!needs.any) return;
  propOpaque_ = gl::ProgramWith<Prop>(build("prop.vert", "prop.frag", shared.contents.defines()));
  if (needs.mask) {
    const auto defines = with({{"CUTOUT", "1"}}, shared.contents.defines());
    propCutout_ = gl::ProgramWith<Prop>(build("prop.vert", "prop.frag", defines));
  }
}

void GeometryPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  builder.write(frame.resources.gbuffer);
}

void GeometryPass::execute(Frame& frame) {
  const GBuffer& gbuffer = *frame.gbuffer;
  bindForOpaqueGeometry(gbuffer);  // depth writes on before the clear, which they mask
  const GLuint fbo = gbuffer.geometryFramebuffer();
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float farDepth = 1.0f;
  for (int i = 0; i < gbuffer::kTargets; ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
  glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);
  const FrameView& view = frame.view;
  for (const Blocks* u : {&opaque_.u, &cutout_.u}) {
    u->viewProjection.set(view.viewProjection);
    u->viewportPixels.set(glm::vec2(gbuffer.size()));
    u->sealMergedEdges.set(true);
  }
  const SectionDraw how{DrawOrder::NearestFirst, glm::vec3(0.0f), shared_.options.cullFacesAway,
                        &frame.stats};
  drawSections(opaque_.id(), opaque_.u.section, shared_.textures, frame.visible, frame.meshes,
               MeshLayer::Opaque, how);
  drawSections(cutout_.id(), cutout_.u.section, shared_.textures, frame.visible, frame.meshes,
               MeshLayer::Cutout, how);
  if (!frame.props) return;
  propOpaque_.u.viewProjection.set(view.viewProjection);
  drawProps(propOpaque_.id(), propOpaque_.u.prop, *frame.props, frame.visibleProps, view.camera,
            AlphaMode::Opaque, true);
  if (propCutout_) {
    propCutout_.u.viewProjection.set(view.viewProjection);
    drawProps(propCutout_.id(), propCutout_.u.prop, *frame.props, frame.visibleProps, view.camera,
              AlphaMode::Mask, true);
  }
}

}  // namespace terrasol
