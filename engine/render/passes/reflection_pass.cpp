#include "render/passes/reflection_pass.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "core/error.h"
#include "core/render_scale.h"
#include "render/gl/render_target.h"
#include "render/gl_slots.h"

namespace terrasol {

namespace {

gl::Framebuffer targetFramebuffer(std::initializer_list<GLuint> colours, GLuint depth) {
  gl::Framebuffer fbo = gl::Framebuffer::create();
  std::vector<GLenum> buffers;
  for (const GLuint colour : colours) {
    const auto slot = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffers.size());
    glNamedFramebufferTexture(fbo.id(), slot, colour, 0);
    buffers.push_back(slot);
  }
  glNamedFramebufferDrawBuffers(fbo.id(), static_cast<GLsizei>(buffers.size()), buffers.data());
  glNamedFramebufferRenderbuffer(fbo.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("a reflection target is incomplete");
  }
  return fbo;
}

constexpr float kZero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, kNotMarched[4] = {0.0f, 0.0f, -1.0f, -1.0f};
constexpr float kFarDepth = 1.0f;

}  // namespace

ReflectionPass::ReflectionPass(const VariantBuilder& build, PassShared& shared) : shared_(shared) {
  if (!shared.options.reflections.enabled) return;
  mask_ = gl::ProgramWith<Mask>(build("fullscreen.vert", "reflection_mask.frag"));
  march_ = gl::ProgramWith<OpaqueMarch>(
      build("fullscreen.vert", "reflection.frag", with(shared.contents.defines(), shared.skyDefines())));
  composite_ = gl::ProgramWith<Composite>(build("fullscreen.vert", "reflection_composite.frag"));
  depthCopy_ = build("fullscreen.vert", "reflection_depth.frag");
  const std::vector<ShaderDefine> surface = with(shared.contents.defines(), surfaceDefines(shared.options));
  surfaceDepth_ = gl::ProgramWith<SurfaceDepth>(build("gbuffer.vert", "depth_only.frag", surface));
  surfaceMarch_ = gl::ProgramWith<SurfaceMarch>(
      build("gbuffer.vert", "surface_reflection.frag", with(surface, shared.skyDefines())));
}

void ReflectionPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  const ReflectionSettings& settings = shared_.options.reflections;
  opaque_ = surfaces_ = false;
  if (!settings.enabled) return builder.skip("reflections are off");
  const bool cull = shared_.options.cullPasses;
  const bool anySmooth = shared_.maxSmoothness >= settings.minSmoothness;
  surfaces_ = anySmooth && (!cull || quadsIn(frame.visible, MeshLayer::Translucent) > 0);
  // Props' materials may be smooth: they are not looked into.
  opaque_ = frame.props || (anySmooth && (!cull || smoothInView(frame)));
  if (!opaque_ && !surfaces_) {
    return builder.skip(anySmooth ? "nothing in view is smooth enough or translucent"
                                  : "no loaded texture is smooth enough");
  }
  builder.read(frame.resources.gbuffer);
  builder.read(frame.resources.scene);
  if (opaque_) builder.write(frame.resources.scene);
  builder.write(frame.resources.reflections);
}

// Whether a section in view has an opaque or cutout face whose texture reaches min_smoothness somewhere.
bool ReflectionPass::smoothInView(const Frame& frame) const {
  const std::vector<float>& smoothness = shared_.smoothness;
  for (const VisibleSection& v : frame.visible) {
    for (const std::uint16_t t : v.section->textures) {
      if (t < smoothness.size() && smoothness[t] >= shared_.options.reflections.minSmoothness) return true;
    }
  }
  return false;
}

void ReflectionPass::ensureTargets(glm::ivec2 size) {
  if (size == size_) return;
  size_ = size;
  colour_ = targetTexture(GL_RGBA16F, size, GL_LINEAR);
  hits_ = targetTexture(GL_RGBA32F, size, GL_LINEAR);
  surfaceReflected_ = targetTexture(GL_RGBA16F, size, GL_LINEAR);
  surfaceHits_ = targetTexture(GL_RGBA32F, size, GL_LINEAR);
  surfaceNormals_ = targetTexture(GL_RGBA16F, size, GL_LINEAR);
  depth_ = gl::Renderbuffer::create();
  glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, size.x, size.y);
  static_assert(slots::kOutColor == 0 && slots::kOutReflectionHit == 1 && slots::kOutReflectionSurface == 2);
  target_ = targetFramebuffer({colour_.id(), hits_.id()}, depth_.id());
  surfaceTarget_ =
      targetFramebuffer({surfaceReflected_.id(), surfaceHits_.id(), surfaceNormals_.id()}, depth_.id());
}

void ReflectionPass::setUniforms(const Frame& frame) const {
  const ReflectionSettings& settings = shared_.options.reflections;
  const FrameView& view = frame.view;
  for (const March* u : {&march_.u.march, &surfaceMarch_.u.march}) {
    u->lighting.set(view);
    u->sky.set(view);
    u->ssr.set(view, settings);
  }
  mask_.u.minSmoothness.set(settings.minSmoothness);
  composite_.u.minSmoothness.set(settings.minSmoothness);
  composite_.u.nearFar.set(view.nearFar);
  surfaceDepth_.u.viewProjection.set(view.viewProjection);
  if (shared_.options.water.waves) surfaceMarch_.u.waves.set(frame.inputs);
}

void ReflectionPass::execute(Frame& frame) {
  const GBuffer& gbuffer = *frame.gbuffer;
  const float scale =
      std::clamp(shared_.options.reflections.resolutionScale, kMinRenderScale, kMaxRenderScale);
  const glm::ivec2 size = glm::max(glm::ivec2(glm::round(glm::vec2(gbuffer.size()) * scale)), glm::ivec2(1));
  ensureTargets(size);
  setUniforms(frame);
  mask_.u.targetSize.set(size);
  march_.u.targetSize.set(size);
  frame.reflections = {};
  glViewport(0, 0, size.x, size.y);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindTextureUnit(slots::kUnitReflectionScene, gbuffer.scene());
  glBindTextureUnit(slots::kUnitSsrDepth, gbuffer.depth());
  // Water and glass first: the opaque part then draws into the scene they reflect. The G-buffer's
  // units are bound after the atlas's, which share some of them.
  if (surfaces_) marchFromSurfaces(frame);
  gbuffer.bindForReading();
  if (opaque_) marchFromOpaque(frame);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

void ReflectionPass::marchFromOpaque(Frame& frame) {
  const GBuffer& gbuffer = *frame.gbuffer;
  frame.reflections.added = colour_.id();
  frame.reflections.hits = hits_.id();
  // The mask, then the march only where it left depth 0 (the triangle lies at depth 1).
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glClearNamedFramebufferfv(target_.id(), GL_COLOR, slots::kOutColor, kZero);
  glClearNamedFramebufferfv(target_.id(), GL_COLOR, slots::kOutReflectionHit, kNotMarched);
  glClearNamedFramebufferfv(target_.id(), GL_DEPTH, 0, &kFarDepth);
  glDisable(GL_CULL_FACE);
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
}

void ReflectionPass::marchFromSurfaces(Frame& frame) {
  frame.reflections.surfaceReflected = surfaceReflected_.id();
  frame.reflections.surfaceHits = surfaceHits_.id();
  glBindFramebuffer(GL_FRAMEBUFFER, surfaceTarget_.id());
  glClearNamedFramebufferfv(surfaceTarget_.id(), GL_COLOR, slots::kOutColor, kZero);
  glClearNamedFramebufferfv(surfaceTarget_.id(), GL_COLOR, slots::kOutReflectionHit, kNotMarched);
  glClearNamedFramebufferfv(surfaceTarget_.id(), GL_COLOR, slots::kOutReflectionSurface, kZero);
  glBindTextureUnit(gbuffer::kDepthUnit, frame.gbuffer->depth());
  // The opaque depth, then the translucent quads' depth over it, with no colour.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glBindVertexArray(shared_.empty.id());
  glUseProgram(depthCopy_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_CULL_FACE);
  glCullFace(frame.view.underWater ? GL_FRONT : GL_BACK);  // as the translucent pass draws them
  glDepthFunc(GL_LESS);
  const SectionDraw nearestFirst{DrawOrder::NearestFirst, glm::vec3(0.0f), !frame.view.underWater, nullptr};
  drawSections(surfaceDepth_.id(), surfaceDepth_.u.section, shared_.textures, frame.visible, frame.meshes,
               MeshLayer::Translucent, nearestFirst);
  // The march, once per pixel: on the nearest quad only.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  surfaceMarch_.u.march.ssr.viewProjection.set(frame.view.viewProjection);
  drawSections(surfaceMarch_.id(), surfaceMarch_.u.section, shared_.textures, frame.visible, frame.meshes,
               MeshLayer::Translucent, nearestFirst);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
}

ReflectionPixels ReflectionPass::read() const {
  ReflectionPixels out;
  if (!colour_) return out;
  out.size = size_;
  const std::size_t pixels = static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y);
  out.added.resize(pixels);
  out.hits.resize(pixels);
  const auto bytes = static_cast<GLsizei>(pixels * sizeof(glm::vec4));
  if (opaque_) {
    glGetTextureImage(colour_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.added.data());
    glGetTextureImage(hits_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.hits.data());
  } else {
    std::fill(out.hits.begin(), out.hits.end(), glm::vec4(0.0f, 0.0f, -1.0f, -1.0f));
  }
  if (surfaces_) {
    for (auto* v : {&out.surfaceReflected, &out.surfaceHits, &out.surfaceNormals}) v->resize(pixels);
    glGetTextureImage(surfaceReflected_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.surfaceReflected.data());
    glGetTextureImage(surfaceHits_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.surfaceHits.data());
    glGetTextureImage(surfaceNormals_.id(), 0, GL_RGBA, GL_FLOAT, bytes, out.surfaceNormals.data());
  }
  return out;
}

}  // namespace terrasol
