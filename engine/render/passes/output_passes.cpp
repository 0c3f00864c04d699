#include "render/passes/output_passes.h"

#include "render/gl/render_target.h"
#include "render/gl_slots.h"

namespace terrasol {

namespace {

// Scales the scene's radiance (noon sun ~3, full sky light 1) into the tone curve's range, so a
// sunlit surface shows about its texture colour, as in vanilla.
constexpr float kExposure = 0.3f;

void drawFullScreen(GLuint program, const PassShared& shared, GLenum mode, GLsizei vertices) {
  glUseProgram(program);
  glBindVertexArray(shared.empty.id());
  glDrawArrays(mode, 0, vertices);
  glBindVertexArray(0);
  glUseProgram(0);
}

void bindTarget(const Frame& frame, GLuint framebuffer) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, frame.targetSize.x, frame.targetSize.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
}

}  // namespace

FxaaPass::FxaaPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      fxaa_(shared.options.antialiasing == Antialiasing::Fxaa ? build("fullscreen.vert", "fxaa.frag").program
                                                              : gl::Program()) {}

std::pair<GLuint, GLuint> FxaaPass::image(glm::ivec2 size) {
  if (size_ != size) {
    size_ = size;
    image_ = targetTexture(GL_RGBA8, size, GL_LINEAR);
    framebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, image_.id(), 0);
  }
  return {image_.id(), framebuffer_.id()};
}

void FxaaPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!frame.finalImage) return builder.skip("anti-aliasing is off");
  builder.read(frame.resources.image);
  builder.write(frame.resources.target);
}

void FxaaPass::execute(Frame& frame) {
  bindTarget(frame, frame.target);
  glBindTextureUnit(0, frame.finalImage);
  drawFullScreen(fxaa_.id(), shared_, GL_TRIANGLES, 3);
}

FinalPass::FinalPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      final_(build("fullscreen.vert", "final.frag")),
      sharpened_(shared.options.antialiasing == Antialiasing::Taa
                     ? build("fullscreen.vert", "final.frag", {{"SHARPEN", ""}})
                     : LinkedProgram()),
      upscale_(build("fullscreen.vert", "upscale.frag")) {}

void FinalPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  builder.read(frame.temporal ? frame.resources.resolved : frame.resources.scene);
  builder.write(frame.finalImage ? frame.resources.image : frame.resources.target);
}

void FinalPass::execute(Frame& frame) {
  if (frame.temporal) {  // TAA resolved the scene at the target's size
    glBindTextureUnit(0, frame.resolved);
    sharpened_.u.exposure.set(kExposure);
    bindTarget(frame, frame.finalTarget);
    drawFullScreen(sharpened_.id(), shared_, GL_TRIANGLES, 3);
    return;
  }
  glBindTextureUnit(0, frame.gbuffer->scene());
  final_.u.exposure.set(kExposure);
  if (frame.size == frame.targetSize) {
    bindTarget(frame, frame.finalTarget);
    drawFullScreen(final_.id(), shared_, GL_TRIANGLES, 3);
    return;
  }
  if (imageSize_ != frame.size) {
    imageSize_ = frame.size;
    image_ = targetTexture(GL_RGBA8, frame.size, GL_NEAREST);
    imageTarget_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(imageTarget_.id(), GL_COLOR_ATTACHMENT0, image_.id(), 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, imageTarget_.id());
  glViewport(0, 0, frame.size.x, frame.size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  drawFullScreen(final_.id(), shared_, GL_TRIANGLES, 3);

  bindTarget(frame, frame.finalTarget);
  glBindTextureUnit(0, image_.id());
  const glm::vec2 scale = glm::vec2(frame.size) / glm::vec2(frame.targetSize);
  upscale_.u.sceneScale.set(scale);
  drawFullScreen(upscale_.id(), shared_, GL_TRIANGLES, 3);
}

DebugViewPass::DebugViewPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared), debug_(build("fullscreen.vert", "debug_view.frag", shared.contents.defines())) {}

void DebugViewPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (frame.inputs.debugView == DebugView::None) return builder.skip("no debug view is chosen");
  builder.read(frame.resources.gbuffer);
  // The reflection views keep the reflection pass (and what it reads) when it has work to do.
  if (showsReflections(frame.inputs.debugView) && builder.written(frame.resources.reflections)) {
    builder.read(frame.resources.reflections);
  }
  builder.write(frame.resources.target);
}

void DebugViewPass::execute(Frame& frame) {
  const Debug& u = debug_.u;
  u.view.set(static_cast<int>(frame.inputs.debugView));
  bindTarget(frame, frame.target);
  frame.gbuffer->bindForReading();
  glBindTextureUnit(slots::kUnitReflection, frame.reflections.added);
  glBindTextureUnit(slots::kUnitReflectionHits, frame.reflections.hits);
  u.reflected.set(frame.reflections.hits != 0);
  glBindTextureUnit(slots::kUnitSurfaceReflection, frame.reflections.surfaceReflected);
  glBindTextureUnit(slots::kUnitSurfaceReflectionHits, frame.reflections.surfaceHits);
  u.surfaceMarched.set(frame.reflections.surfaceHits != 0);
  u.nearFar.set(frame.view.nearFar);
  drawFullScreen(debug_.id(), shared_, GL_TRIANGLES, 3);
}

OutlinePass::OutlinePass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared), outline_(build("outline.vert", "outline.frag")) {}

void OutlinePass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!frame.inputs.outline) return builder.skip("no block is targeted");
  builder.read(frame.resources.gbuffer);  // its depth
  builder.read(frame.resources.target);
  builder.write(frame.resources.target);
}

void OutlinePass::execute(Frame& frame) {
  constexpr double kGrow = 0.002;  // Minecraft's: keeps the edges off the block's faces
  const WorldBox& box = *frame.inputs.outline;
  bindTarget(frame, frame.target);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindTextureUnit(0, frame.gbuffer->depth());
  const glm::vec2 scale = glm::vec2(frame.size) / glm::vec2(frame.targetSize);
  outline_.u.depthScale.set(scale);
  outline_.u.min.set(glm::vec3(box.min - kGrow - frame.view.camera));
  outline_.u.max.set(glm::vec3(box.max + kGrow - frame.view.camera));
  outline_.u.viewProjection.set(frame.view.unjittered);
  drawFullScreen(outline_.id(), shared_, GL_LINES, 24);
  glDisable(GL_BLEND);
}

}  // namespace terrasol
