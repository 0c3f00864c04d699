#include "render/passes/geometry_pass.h"

#include "render/gl/uniforms.h"
#include "render/prop_draw.h"
#include "render/section_draw.h"

namespace terrasol {

GeometryPass::GeometryPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      opaque_(build("gbuffer.vert", "gbuffer.frag", shared.contents.defines())),
      cutout_(build("gbuffer.vert", "gbuffer.frag", with({{"CUTOUT", "1"}}, shared.contents.defines()))) {
  const PropNeeds& needs = shared.options.props;
  if (!needs.any) return;
  propOpaque_ = build("prop.vert", "prop.frag", shared.contents.defines());
  if (needs.mask)
    propCutout_ = build("prop.vert", "prop.frag", with({{"CUTOUT", "1"}}, shared.contents.defines()));
}

void GeometryPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  builder.write(frame.resources.gbuffer);
}

void GeometryPass::execute(Frame& frame) {
  const GBuffer& gbuffer = *frame.gbuffer;
  const GLuint fbo = gbuffer.geometryFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, gbuffer.size().x, gbuffer.size().y);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float farDepth = 1.0f;
  for (int i = 0; i < gbuffer::kTargets; ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
  glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const FrameView& view = frame.view;
  for (const GLuint program : {opaque_.id(), cutout_.id()}) {
    gl::setMat4(program, "u_viewProjection", view.viewProjection);
    glProgramUniform2f(program, glGetUniformLocation(program, "u_viewportPixels"),
                       static_cast<float>(gbuffer.size().x), static_cast<float>(gbuffer.size().y));
    glProgramUniform1i(program, glGetUniformLocation(program, "u_sealMergedEdges"), 1);
  }
  const SectionDraw how{DrawOrder::NearestFirst, glm::vec3(0.0f), shared_.options.cullFacesAway,
                        &frame.stats};
  drawSections(opaque_.id(), shared_.textures, frame.visible, frame.meshes, MeshLayer::Opaque, how);
  drawSections(cutout_.id(), shared_.textures, frame.visible, frame.meshes, MeshLayer::Cutout, how);
  if (!frame.props) return;
  gl::setMat4(propOpaque_.id(), "u_viewProjection", view.viewProjection);
  drawProps(propOpaque_.id(), *frame.props, frame.visibleProps, view.camera, AlphaMode::Opaque, true);
  if (propCutout_.id()) {
    gl::setMat4(propCutout_.id(), "u_viewProjection", view.viewProjection);
    drawProps(propCutout_.id(), *frame.props, frame.visibleProps, view.camera, AlphaMode::Mask, true);
  }
}

}  // namespace terrasol
