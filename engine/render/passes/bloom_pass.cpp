#include "render/passes/bloom_pass.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/gl/render_target.h"
#include "render/section_draw.h"

namespace terrasol {

namespace {

// Levels down to about 8 pixels on the short side, at most this many: the widest spread is then about
// 2^kMaxLevels scene pixels.
constexpr int kMaxLevels = 6;
constexpr int kSmallestSide = 8;
constexpr float kSpread = 0.6f;
constexpr float kGlowDegrees = 25.0f;
constexpr float kBelowHorizon = -0.1f;  // sine of the elevation below which the ground hides a disc

}  // namespace

BloomPass::BloomPass(const VariantBuilder& build, PassShared& shared) : shared_(shared) {
  if (!shared.options.bloom.enabled) return;
  down_ = build("fullscreen.vert", "bloom_down.frag");
  up_ = gl::ProgramWith<Up>(build("fullscreen.vert", "bloom_up.frag"));
  composite_ = gl::ProgramWith<Composite>(build("fullscreen.vert", "bloom_composite.frag"));
}

void BloomPass::realize(glm::ivec2 sceneSize) {
  if (sceneSize_ == sceneSize) return;
  sceneSize_ = sceneSize;
  levels_.clear();
  glm::ivec2 size = sceneSize;
  while (static_cast<int>(levels_.size()) < kMaxLevels && std::min(size.x, size.y) / 2 >= kSmallestSide) {
    size = (size + 1) / 2;
    Level level{size, targetTexture(GL_R11F_G11F_B10F, size, GL_NEAREST),
                targetTexture(GL_R11F_G11F_B10F, size, GL_NEAREST), gl::Framebuffer::create(),
                gl::Framebuffer::create()};
    glNamedFramebufferTexture(level.downTarget.id(), GL_COLOR_ATTACHMENT0, level.down.id(), 0);
    glNamedFramebufferTexture(level.upTarget.id(), GL_COLOR_ATTACHMENT0, level.up.id(), 0);
    levels_.push_back(std::move(level));
  }
}

void BloomPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!shared_.options.bloom.enabled || shared_.options.bloom.strength <= 0.0f)
    return builder.skip("bloom is off");
  if (frame.inputs.debugView != DebugView::None) return builder.skip("a debug view is shown");
  if (shared_.options.cullPasses && !brightInView(frame)) return builder.skip("nothing in view is bright");
  builder.read(frame.resources.scene);
  builder.write(frame.resources.scene);
}

// Whether anything in view can be brighter than its surroundings by far: an emissive texture, a prop
// (its emission is not known here), the sun's or the moon's disc and glow, or while the light is up a
// glint off water, glass or a smooth block. Without any, bloom would only blur the frame a little.
bool BloomPass::brightInView(const Frame& frame) const {
  const FrameView& view = frame.view;
  for (const VisibleSection& v : frame.visible) {
    for (const std::uint16_t t : v.section->textures) {
      if (t < shared_.emission.size() && shared_.emission[t] > 0.0f) return true;
      if (view.lightUp && t < shared_.smoothness.size() &&
          shared_.smoothness[t] >= shared_.options.reflections.minSmoothness)
        return true;
    }
  }
  if (!frame.visibleProps.empty()) return true;
  if (view.lightUp && quadsIn(frame.visible, MeshLayer::Translucent) > 0) return true;
  // The discs' glow (lib/sky.glsl) is still bright some 25 degrees out: within that of the view's cone,
  // unless the body is well below the horizon (the ground hides it).
  const float halfDiagonal = glm::degrees(std::atan(std::tan(glm::radians(view.cone.fovDegrees * 0.5f)) *
                                                    std::sqrt(1.0f + view.cone.aspect * view.cone.aspect)));
  const float reach = std::cos(glm::radians(std::min(halfDiagonal + kGlowDegrees, 180.0f)));
  const glm::vec3 forward(view.forward);
  const auto inView = [&](glm::vec3 to) { return to.y > kBelowHorizon && glm::dot(forward, to) >= reach; };
  return inView(view.day.toSun) || inView(view.day.toMoon);
}

void BloomPass::draw(GLuint program, GLuint framebuffer, glm::ivec2 size) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  glUseProgram(program);
  glBindVertexArray(shared_.empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void BloomPass::execute(Frame& frame) {
  realize(frame.size);
  if (levels_.empty()) return;  // a frame too small to spread light across
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  GLuint source = frame.gbuffer->scene();
  for (const Level& level : levels_) {
    glBindTextureUnit(0, source);
    draw(down_.id(), level.downTarget.id(), level.size);
    source = level.down.id();
  }
  // The smallest level is its own sum; each larger one adds the sum below it, scaled up.
  GLuint below = levels_.back().down.id();
  for (int i = static_cast<int>(levels_.size()) - 2; i >= 0; --i) {
    const Level& level = levels_[static_cast<std::size_t>(i)];
    glBindTextureUnit(0, level.down.id());
    glBindTextureUnit(1, below);
    up_.u.spread.set(kSpread);
    draw(up_.id(), level.upTarget.id(), level.size);
    below = level.up.id();
  }
  // Into the scene: its colour kept at (1 - strength), its alpha (the shadow term) kept whole.
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glBindTextureUnit(0, below);
  composite_.u.strength.set(shared_.options.bloom.strength);
  // 1 + kSpread + kSpread^2 + ... over the levels.
  const float weights = (1.0f - std::pow(kSpread, static_cast<float>(levels_.size()))) / (1.0f - kSpread);
  composite_.u.weights.set(weights);
  draw(composite_.id(), frame.gbuffer->lightingFramebuffer(), frame.size);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace terrasol
