#include "render/passes/taa_pass.h"

#include <cmath>
#include <vector>

#include "render/gl/render_target.h"

namespace terrasol {

TaaPass::TaaPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      resolve_(shared.options.antialiasing == Antialiasing::Taa ? build("fullscreen.vert", "taa.frag")
                                                                : LinkedProgram()) {}

void TaaPass::realize(glm::ivec2 size) {
  if (size_ == size) return;
  size_ = size;
  for (int i = 0; i < 2; ++i) {
    history_[i] = targetTexture(GL_RGBA16F, size, GL_LINEAR);
    target_[i] = gl::Framebuffer::create();
    glNamedFramebufferTexture(target_[i].id(), GL_COLOR_ATTACHMENT0, history_[i].id(), 0);
  }
  historyValid_ = false;
}

void TaaPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!frame.temporal) return builder.skip("anti-aliasing is not temporal");
  builder.read(frame.resources.scene);
  builder.read(frame.resources.gbuffer);  // its depth
  builder.write(frame.resources.resolved);
}

void TaaPass::execute(Frame& frame) {
  realize(frame.targetSize);
  const FrameView& view = frame.view;
  const int last = current_;
  current_ = 1 - current_;
  glBindFramebuffer(GL_FRAMEBUFFER, target_[current_].id());
  glViewport(0, 0, size_.x, size_.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glBindTextureUnit(0, frame.gbuffer->scene());
  glBindTextureUnit(1, frame.gbuffer->depth());
  glBindTextureUnit(2, history_[last].id());
  glBindTextureUnit(3, frame.reactive);
  const Resolve& u = resolve_.u;
  u.inverseViewProjection.set(view.inverseViewProjection);
  u.reprojection.set(lastViewProjection_);
  // Small in float: the camera's step since the last frame, taken in double.
  u.cameraMotion.set(glm::vec3(view.camera - lastCamera_));
  u.jitter.set(view.jitter);
  u.sceneScale.set(glm::vec2(frame.size) / glm::vec2(frame.targetSize));
  u.historyValid.set(historyValid_);
  u.reactive.set(frame.reactive != 0);
  glUseProgram(resolve_.id());
  glBindVertexArray(shared_.empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);

  frame.resolved = history_[current_].id();
  jitterFrame_ = nextJitterFrame() + 1;
  historyValid_ = true;
  lastViewProjection_ = view.unjittered;
  lastCamera_ = view.camera;
}

std::size_t TaaPass::nonFinitePixels() const {
  if (!historyValid_) return 0;
  std::vector<float> pixels(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y) * 4);
  glGetTextureImage(history_[current_].id(), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
  std::size_t bad = 0;
  for (std::size_t p = 0; p < pixels.size(); p += 4) {
    bad += !(std::isfinite(pixels[p]) && std::isfinite(pixels[p + 1]) && std::isfinite(pixels[p + 2]) &&
             std::isfinite(pixels[p + 3]));
  }
  return bad;
}

}  // namespace terrasol
