#include "render/passes/translucent_pass.h"

#include "render/gl/render_target.h"
#include "render/gl_slots.h"

namespace terrasol {
namespace {

constexpr float kNothingReactive[4] = {0.0f, 0.0f, 0.0f, 0.0f};

}  // namespace

TranslucentPass::TranslucentPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared),
      blocks_(build("gbuffer.vert", "translucent.frag",
                    with(with(with(lightingDefines(shared.options), shared.contents.defines()),
                              surfaceDefines(shared.options)),
                         shared.skyDefines()))) {
  if (!shared.options.props.blend) return;
  const auto defines =
      with(with(lightingDefines(shared.options), shared.contents.defines()), shared.skyDefines());
  props_ = gl::ProgramWith<Prop>(build("prop.vert", "prop_translucent.frag", defines));
}

void TranslucentPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  const bool props = frame.props && props_ && anyBlended(*frame.props, frame.visibleProps);
  if (shared_.options.cullPasses && quadsIn(frame.visible, MeshLayer::Translucent) == 0 && !props) {
    return builder.skip("no translucent geometry in view");
  }
  builder.read(frame.resources.gbuffer);  // its depth
  if (shared_.options.shadow.enabled) builder.read(frame.resources.shadowMap);
  builder.read(frame.resources.scene);
  if (builder.written(frame.resources.reflections)) builder.read(frame.resources.reflections);
  builder.write(frame.resources.scene);
}

void TranslucentPass::execute(Frame& frame) {
  const FrameView& view = frame.view;
  blocks_.u.lit.set(view, frame.shadow);
  if (shared_.options.reflections.enabled) prepareReflections(frame);
  if (shared_.options.water.waves) blocks_.u.waves.set(frame.inputs);
  const GLuint target = frame.gbuffer->translucentFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glViewport(0, 0, frame.gbuffer->size().x, frame.gbuffer->size().y);
  if (frame.temporal) markReactive(frame);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);  // tested against the opaque scene, never hiding each other
  glEnable(GL_CULL_FACE);
  glCullFace(view.underWater ? GL_FRONT : GL_BACK);  // under water the surface is seen from below
  glEnable(GL_BLEND);
  // Premultiplied colour; alpha keeps the lighting pass's shadow term of the surface behind.
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  blocks_.u.viewProjection.set(view.viewProjection);
  drawSections(blocks_.id(), blocks_.u.section, shared_.textures, frame.visible, frame.meshes,
               MeshLayer::Translucent, {DrawOrder::FarthestFirst, glm::vec3(0.0f), false, &frame.stats});
  if (frame.props && props_) {
    glCullFace(GL_BACK);
    props_.u.lit.set(view, frame.shadow);
    props_.u.viewProjection.set(view.viewProjection);
    drawProps(props_.id(), props_.u.prop, *frame.props, frame.visibleProps, view.camera, AlphaMode::Blend,
              true);
  }
  glDisable(GL_BLEND);
  glCullFace(GL_BACK);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  if (frame.temporal) {
    glBlendEquationi(slots::kOutReactive, GL_FUNC_ADD);
    glNamedFramebufferDrawBuffer(target, GL_COLOR_ATTACHMENT0);
  }
}

// With TAA, the reactive mask too: water changes by itself (its animated texture, its waves, what it
// refracts and reflects), and a history a dozen frames deep shows it blurred in time. The nearest
// water's mark wins (max), whatever lies over it.
void TranslucentPass::markReactive(Frame& frame) const {
  const GLuint target = frame.gbuffer->translucentFramebuffer();
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT0 + slots::kOutReactive};
  static_assert(slots::kOutColor == 0 && slots::kOutReactive == 1);
  glNamedFramebufferDrawBuffers(target, 2, buffers);
  glClearNamedFramebufferfv(target, GL_COLOR, slots::kOutReactive, kNothingReactive);
  glBlendEquationi(slots::kOutReactive, GL_MAX);
  frame.reactive = frame.gbuffer->reactive();
}

// The lit opaque scene as it is now and its depth, for water to refract; and the reflection pass's
// march from water and glass.
void TranslucentPass::prepareReflections(const Frame& frame) {
  const GBuffer& gbuffer = *frame.gbuffer;
  if (copySize_ != gbuffer.size()) {
    copySize_ = gbuffer.size();
    sceneCopy_ = targetTexture(GL_RGBA16F, copySize_, GL_NEAREST);  // read by texel
  }
  glCopyImageSubData(gbuffer.scene(), GL_TEXTURE_2D, 0, 0, 0, 0, sceneCopy_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                     copySize_.x, copySize_.y, 1);
  glBindTextureUnit(slots::kUnitReflectionScene, sceneCopy_.id());
  glBindTextureUnit(slots::kUnitSsrDepth, gbuffer.lightingDepth());
  blocks_.u.nearFar.set(frame.view.nearFar);
  blocks_.u.minSmoothness.set(shared_.options.reflections.minSmoothness);
  // What the reflection pass's march from these surfaces saw, where it ran.
  const ReflectionTargets& marched = frame.reflections;
  blocks_.u.marched.set(marched.surfaceReflected != 0);
  glBindTextureUnit(slots::kUnitReflection, marched.surfaceReflected);
  glBindTextureUnit(slots::kUnitReflectionHits, marched.surfaceHits);
}

}  // namespace terrasol
