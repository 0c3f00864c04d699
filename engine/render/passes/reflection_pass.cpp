#include "render/passes/reflection_pass.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/frame_uniforms.h"
#include "render/gl/uniforms.h"
#include "render/gl_slots.h"

namespace terrasol {

ReflectionPass::ReflectionPass(const VariantBuilder& build, PassShared& shared) : shared_(shared) {
  if (!shared.options.reflections.enabled) return;
  mask_ = build("fullscreen.vert", "reflection_mask.frag");
  march_ = build("fullscreen.vert", "reflection.frag", shared.contents.defines());
  composite_ = build("fullscreen.vert", "reflection_composite.frag");
}

void ReflectionPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  const ReflectionSettings& settings = shared_.options.reflections;
  if (!settings.enabled) return builder.skip("reflections are off");
  if (!frame.props) {  // props' materials may be smooth: they are not looked into
    if (shared_.maxSmoothness < settings.minSmoothness)
      return builder.skip("no loaded texture is smooth enough");
    if (shared_.options.cullPasses && !smoothInView(frame))
      return builder.skip("nothing in view is smooth enough");
  }
  builder.read(frame.resources.gbuffer);
  builder.read(frame.resources.scene);
  builder.write(frame.resources.scene);
  builder.write(frame.resources.reflections);
}

// Whether a section in view has a face whose texture reaches min_smoothness somewhere.
bool ReflectionPass::smoothInView(const Frame& frame) const {
  const std::vector<float>& smoothness = shared_.smoothness;
  for (const VisibleSection& v : frame.visible) {
    for (const std::uint16_t t : v.section->textures) {
      if (t < smoothness.size() && smoothness[t] >= shared_.options.reflections.minSmoothness) return true;
    }
  }
  return false;
}

void ReflectionPass::ensureTarget(glm::ivec2 size) {
  if (size == size_) return;
  size_ = size;
  colour_ = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(colour_.id(), 1, GL_RGBA16F, size.x, size.y);
  glTextureParameteri(colour_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(colour_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(colour_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(colour_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  hits_ = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(hits_.id(), 1, GL_RGBA32F, size.x, size.y);
  depth_ = gl::Renderbuffer::create();
  glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, size.x, size.y);
  target_ = gl::Framebuffer::create();
  glNamedFramebufferTexture(target_.id(), GL_COLOR_ATTACHMENT0 + slots::kOutColor, colour_.id(), 0);
  glNamedFramebufferTexture(target_.id(), GL_COLOR_ATTACHMENT0 + slots::kOutReflectionHit, hits_.id(), 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(target_.id(), 2, buffers);
  glNamedFramebufferRenderbuffer(target_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  if (glCheckNamedFramebufferStatus(target_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("the reflection target is incomplete");
  }
}

void ReflectionPass::setMarchUniforms(const Frame& frame) const {
  const ReflectionSettings& settings = shared_.options.reflections;
  const FrameView& view = frame.view;
  const GLuint program = march_.id();
  setLightingUniforms(program, view, frame.shadow);
  setSkyUniforms(program, view);
  setSsrUniforms(program, view, settings);
  for (const GLuint p : {mask_.id(), composite_.id()}) {
    glProgramUniform1f(p, glGetUniformLocation(p, "u_minSmoothness"), settings.minSmoothness);
  }
  glProgramUniform2fv(composite_.id(), glGetUniformLocation(composite_.id(), "u_nearFar"), 1,
                      glm::value_ptr(view.nearFar));
}

void ReflectionPass::execute(Frame& frame) {
  const GBuffer& gbuffer = *frame.gbuffer;
  const float scale = std::clamp(shared_.options.reflections.resolutionScale, 0.25f, 1.0f);
  const glm::ivec2 size = glm::max(glm::ivec2(glm::round(glm::vec2(gbuffer.size()) * scale)), glm::ivec2(1));
  ensureTarget(size);
  frame.reflections = {colour_.id(), hits_.id()};
  setMarchUniforms(frame);

  // The mask, then the march only where it left depth 0 (the triangle lies at depth 1).
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glViewport(0, 0, size.x, size.y);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, notMarched[4] = {0.0f, 0.0f, -1.0f, -1.0f}, farDepth = 1.0f;
  glClearNamedFramebufferfv(target_.id(), GL_COLOR, slots::kOutColor, zero);
  glClearNamedFramebufferfv(target_.id(), GL_COLOR, slots::kOutReflectionHit, notMarched);
  glClearNamedFramebufferfv(target_.id(), GL_DEPTH, 0, &farDepth);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  gbuffer.bindForReading();
  glBindTextureUnit(slots::kUnitReflectionScene, gbuffer.scene());
  glBindTextureUnit(slots::kUnitSsrDepth, gbuffer.depth());
  glBindVertexArray(shared_.empty.id());
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  // The mask writes depth only: a shader without a colour output leaves undefined colour behind.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glUseProgram(mask_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glUseProgram(march_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);

  // Added where something was drawn (the lighting pass's copy of the scene's depth), alpha kept. The
  // scene is drawn into now, so it is no longer bound for reading.
  glBindTextureUnit(slots::kUnitReflectionScene, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.lightingFramebuffer());
  glViewport(0, 0, gbuffer.size().x, gbuffer.size().y);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
  glBindTextureUnit(slots::kUnitReflection, colour_.id());
  glBindTextureUnit(slots::kUnitReflectionHits, hits_.id());
  glUseProgram(composite_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

ReflectionPixels ReflectionPass::read() const {
  ReflectionPixels out;
  if (!colour_) return out;
  out.size = size_;
  const std::size_t pixels = static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y);
  out.added.resize(pixels);
  out.hits.resize(pixels);
  const auto bytes = static_cast<GLsizei>(pixels * sizeof(glm::vec4));
  glGetTextureImage(colour_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.added.data());
  glGetTextureImage(hits_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.hits.data());
  return out;
}

}  // namespace terrasol
