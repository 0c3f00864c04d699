#include "render/passes/lighting_pass.h"

namespace terrasol {

LightingPass::LightingPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      lighting_(
          build("fullscreen.vert", "lighting.frag",
                with(with(lightingDefines(shared.options), shared.contents.defines()), shared.skyDefines()))),
      sky_(build("fullscreen.vert", "sky.frag", shared.skyDefines())) {}

void LightingPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  builder.read(frame.resources.gbuffer);
  if (shared_.options.shadow.enabled) builder.read(frame.resources.shadowMap);
  builder.write(frame.resources.scene);
}

void LightingPass::execute(Frame& frame) {
  const FrameView& view = frame.view;
  const GLuint program = lighting_.id();
  lighting_.u.lit.set(view, frame.shadow);
  lighting_.u.inverseViewProjection.set(view.inverseViewProjection);
  sky_.u.sky.set(view);
  sky_.u.inverseViewProjection.set(view.inverseViewProjection);

  const GBuffer& gbuffer = *frame.gbuffer;
  gbuffer.copyDepthForLighting();
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.lightingFramebuffer());
  glViewport(0, 0, gbuffer.size().x, gbuffer.size().y);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  gbuffer.bindForReading();
  glBindVertexArray(shared_.empty.id());
  glUseProgram(program);
  glDepthFunc(GL_GREATER);  // depth 1 lies beyond what was drawn
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(sky_.id());
  glDepthFunc(GL_LEQUAL);  // only the cleared depth, 1, is not nearer
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

}  // namespace terrasol
