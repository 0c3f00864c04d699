#include "render/passes/shafts_pass.h"

#include <algorithm>
#include <string>

#include "render/gl/render_target.h"

namespace terrasol {

ShaftsPass::ShaftsPass(const VariantBuilder& build, PassShared& shared) : shared_(shared) {
  const RendererOptions& o = shared.options;
  if (!o.shafts.enabled || !o.shadow.enabled || o.fog.density <= 0.0f) return;
  const int samples = std::clamp(o.shafts.samples, 1, 64);
  march_ = gl::ProgramWith<March>(build(
      "fullscreen.vert", "shafts.frag",
      with(with(lightingDefines(o), shared.skyDefines()), {{"SHAFT_SAMPLES", std::to_string(samples)}})));
  composite_ = gl::ProgramWith<Composite>(build("fullscreen.vert", "shafts_composite.frag"));
}

void ShaftsPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!march_) return builder.skip("shafts are off (or shadows or fog)");
  if (frame.inputs.debugView != DebugView::None) return builder.skip("a debug view is shown");
  if (!frame.view.lightUp) return builder.skip("neither sun nor moon is above the horizon");
  builder.read(frame.resources.gbuffer);  // its depth
  builder.read(frame.resources.shadowMap);
  builder.read(frame.resources.scene);
  builder.write(frame.resources.scene);
}

void ShaftsPass::realize(glm::ivec2 size) {
  if (size == size_) return;
  size_ = size;
  shafts_ = targetTexture(GL_R11F_G11F_B10F, size, GL_NEAREST);  // read by texel
  target_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(target_.id(), GL_COLOR_ATTACHMENT0, shafts_.id(), 0);
}

void ShaftsPass::execute(Frame& frame) {
  const FrameView& view = frame.view;
  const float scale = std::clamp(shared_.options.shafts.scale, 0.125f, 1.0f);
  realize(glm::max(glm::ivec2(glm::round(glm::vec2(frame.size) * scale)), glm::ivec2(1)));
  const float distance = shared_.options.shadow.distance;
  const March& m = march_.u;
  m.sky.set(view);
  m.shadow.set(frame.shadow, view.lightUp);
  m.inverseViewProjection.set(view.inverseViewProjection);
  m.toLight.set(view.day.toShadowLight);
  m.lightColor.set(view.day.lightColor);
  m.distance.set(distance);
  // Under TAA the samples' start moves with the jitter's frames, and its history averages them.
  frameIndex_ = frame.temporal ? (frameIndex_ + 1) % 64 : 0;
  m.noiseOffset.set(glm::vec2(5.588238f, 3.414f) * static_cast<float>(frameIndex_));

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  frame.gbuffer->bindForReading();
  glBindVertexArray(shared_.empty.id());
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glViewport(0, 0, size_.x, size_.y);
  glUseProgram(march_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Added to the scene; its alpha (the shadow term) kept.
  glBindFramebuffer(GL_FRAMEBUFFER, frame.gbuffer->lightingFramebuffer());
  glViewport(0, 0, frame.size.x, frame.size.y);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
  glBindTextureUnit(0, shafts_.id());
  composite_.u.scale.set(glm::vec2(size_) / glm::vec2(frame.size));
  glUseProgram(composite_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace terrasol
