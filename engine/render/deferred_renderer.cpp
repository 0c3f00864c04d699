#include "render/deferred_renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include "core/camera.h"
#include "core/cloud_layer.h"
#include "core/luma.h"
#include "core/render_scale.h"
#include "core/temporal_jitter.h"
#include "render/cave_culling.h"
#include "render/frame_graph.h"
#include "render/prop_draw.h"
#include "render/section_draw.h"

namespace terrasol {

DeferredRenderer::DeferredRenderer(const ShaderPreprocessor& shaders, const Atlas& atlas,
                                   const TintPalette& tints, const CloudMap& clouds,
                                   const RendererOptions& options)
    : shared_(atlas, tints, clouds, options),
      geometry_(VariantBuilder(shaders, shared_), shared_),
      lod_(VariantBuilder(shaders, shared_), shared_),
      crack_(VariantBuilder(shaders, shared_), shared_, atlas),
      lighting_(VariantBuilder(shaders, shared_), shared_),
      reflection_(VariantBuilder(shaders, shared_), shared_),
      translucent_(VariantBuilder(shaders, shared_), shared_),
      shadow_(VariantBuilder(shaders, shared_), shared_),
      shafts_(VariantBuilder(shaders, shared_), shared_),
      bloom_(VariantBuilder(shaders, shared_), shared_),
      taa_(VariantBuilder(shaders, shared_), shared_),
      final_(VariantBuilder(shaders, shared_), shared_),
      fxaa_(VariantBuilder(shaders, shared_), shared_),
      debug_(VariantBuilder(shaders, shared_), shared_),
      outline_(VariantBuilder(shaders, shared_), shared_),
      gpuTimer_(!softwareRenderer()) {}

glm::ivec2 scaledRenderSize(glm::ivec2 size, float scale) {
  const float s = std::isfinite(scale) ? std::clamp(scale, kMinRenderScale, kMaxRenderScale) : 1.0f;
  if (s >= 1.0f) return size;
  return glm::max(glm::ivec2(glm::round(glm::vec2(size) * s)), glm::ivec2(1));
}

void DeferredRenderer::render(const FrameInputs& inputs, const SectionMeshes& meshes, GLuint framebuffer,
                              glm::ivec2 targetSize, std::vector<PassTiming>* timings) {
  if (targetSize.x <= 0 || targetSize.y <= 0) return;  // a minimised window: nothing to draw
  stats_ = {};
  reflected_ = false;
  // Debug views show the G-buffer texel for texel.
  const glm::ivec2 size =
      inputs.debugView == DebugView::None ? scaledRenderSize(targetSize, inputs.renderScale) : targetSize;
  Frame frame{inputs, meshes, stats_};
  const Antialiasing aa =
      inputs.debugView == DebugView::None ? shared_.options.antialiasing : Antialiasing::None;
  frame.temporal = aa == Antialiasing::Taa && !inputs.aside;
  if (aa != Antialiasing::Taa) taa_.forgetHistory();  // a debug view in between: the history is stale
  const int jitterFrame = inputs.aside ? taa_.lastJitterFrame() : taa_.nextJitterFrame();
  const glm::vec2 jitter =
      aa == Antialiasing::Taa ? jitterAt(jitterFrame, jitterPhases(inputs.renderScale)) : glm::vec2(0.0f);
  frame.view = viewFor(inputs, size, jitter);
  frame.target = framebuffer;
  frame.finalTarget = framebuffer;
  if (aa == Antialiasing::Fxaa) std::tie(frame.finalImage, frame.finalTarget) = fxaa_.image(targetSize);
  frame.size = size;
  frame.targetSize = targetSize;
  frame.shadow = shadow_.lookup();
  shared_.textures.update(inputs.ticks);
  shared_.textures.setDetail(frame.temporal ? static_cast<float>(size.x) / static_cast<float>(targetSize.x)
                                            : 1.0f);

  FrameGraph graph;
  PassClock clock(timings, gpuTimer_);
  frame.props = inputs.props && !inputs.props->empty() && shared_.options.props.any ? inputs.props : nullptr;
  cull(frame);
  const auto realizeTargets = [&] {
    if (!gbuffer_ || gbuffer_->size() != size) gbuffer_.emplace(size, shared_.contents);
    frame.gbuffer = &*gbuffer_;
  };
  frame.resources = {graph.transient("gbuffer", realizeTargets),
                     graph.transient("scene", realizeTargets),
                     graph.import("shadow_map"),
                     graph.import("target"),
                     graph.transient("reflections"),
                     graph.transient("image"),
                     graph.transient("resolved")};
  for (RenderPass* pass : std::initializer_list<RenderPass*>{&shadow_, &geometry_, &lod_, &crack_, &lighting_,
                                                             &reflection_, &translucent_, &shafts_, &bloom_,
                                                             &taa_, &final_, &fxaa_, &debug_, &outline_}) {
    addPass(graph, *pass, frame);
  }
  graph.output(frame.resources.target);
  graph.execute([&](const std::string& pass) { clock.lap(pass); }, shared_.options.cullPasses);

  for (const FrameGraph::Skipped& s : graph.skipped()) stats_.passesSkipped.push_back({s.pass, s.why});
  const FrameView& view = frame.view;
  const auto& ran = graph.executed();
  const bool shown = frame.shadowDrawn && std::find(ran.begin(), ran.end(), "lighting") != ran.end();
  reflected_ = std::find(ran.begin(), ran.end(), "reflection") != ran.end();
  lastGeometry_ = {view.camera,
                   view.viewProjection,
                   view.inverseViewProjection,
                   view.day.toShadowLight,
                   shown,
                   shown ? (*frame.shadow.views)[0].texelWorld : 0.0f};
}

FrameView DeferredRenderer::viewFor(const FrameInputs& inputs, glm::ivec2 size, glm::vec2 jitter) const {
  FrameView view;
  view.camera = inputs.cameraPosition;
  Camera camera;  // at the origin: everything is drawn relative to the camera
  const glm::dvec3 forward = inputs.cameraLookAt - inputs.cameraPosition;
  camera.lookAt = glm::vec3(forward);
  camera.up = glm::vec3(inputs.cameraUp);
  camera.fovDegrees = inputs.fovDegrees;
  camera.farPlane = std::max(2.0f * inputs.viewDistance, 256.0f);
  const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
  view.unjittered = camera.projection(aspect) * camera.view();
  // The jitter moves the image by a fraction of a scene pixel: a shift in clip space after projection.
  glm::mat4 shift(1.0f);
  shift[3] = glm::vec4(2.0f * jitter / glm::vec2(size), 0.0f, 1.0f);
  view.jitter = jitter;
  view.viewProjection = shift * view.unjittered;
  view.inverseViewProjection = glm::inverse(view.viewProjection);
  view.frustum = frustumPlanes(view.unjittered);
  view.nearFar = {camera.nearPlane, camera.farPlane};
  view.fogRange = {0.8f * inputs.viewDistance, inputs.viewDistance};
  view.day = dayStateAt(inputs.ticks, inputs.sunPathRotation);
  view.materialAo = inputs.materialAo;
  view.shadowCentreOffset = inputs.shadowCentreOffset;
  const double forwardLength = glm::length(forward);
  if (forwardLength > 1e-9) view.forward = forward / forwardLength;
  view.lightmap = lightmapColours(view.day, inputs.ticks);
  if (inputs.underWater) {
    // The depths take the water's colour lit by the sky: its tint times the zenith's brightness
    // (lib/sky.glsl) scattered back at a quarter, dimmed by the sky light at the camera squared.
    const float skyLight = std::clamp(inputs.underWater->skyLight, 0.0f, 1.0f);
    const float zenith = luma(view.day.skyZenith);
    view.underWater = true;
    view.waterTop = static_cast<float>(std::max(inputs.underWater->surfaceY - inputs.cameraPosition.y, 0.0));
    view.waterFog = shared_.textures.waterTint() * (kSkyRadiance * 0.25f * zenith * skyLight * skyLight);
  }
  // Below 0.1 % of its strength the light can show nothing (it is 0 at and under the horizon).
  view.lightUp = shared_.options.shadow.enabled && view.day.directStrength > 1e-3f;
  // Receivers down to the world's bottom: the lowest visible section jumps by a hundred blocks as a
  // cave comes into view, and a floor that followed it would have the map redrawn at every jump.
  view.cone.eye = view.camera;
  view.cone.forward = glm::vec3(view.forward);  // unit, or -z for a degenerate look-at
  view.cone.up = camera.up;
  view.cone.fovDegrees = camera.fovDegrees;
  view.cone.aspect = aspect;
  view.cone.farPlane = camera.farPlane;
  view.cone.floorY = kMinY;
  if (const FogSettings& fog = shared_.options.fog; fog.density > 0.0f) {
    // Capped where the camera lies far below the base: the fog there is opaque anyway.
    const double above = (inputs.cameraPosition.y - fog.base) / std::max(fog.falloff, 1.0f);
    view.heightFog = {static_cast<float>(fog.density * std::exp(-std::clamp(above, -20.0, 80.0))),
                      std::max(fog.falloff, 1.0f)};
    // The horizon's light, dimmed by the sky light where the camera is: haze in a cave is dark.
    const float sky = std::clamp(static_cast<float>(inputs.eyeLight.y) / 15.0f, 0.0f, 1.0f);
    view.heightFogColour = view.day.skyHorizon * (kSkyRadiance * sky * sky);
  }
  if (shared_.clouds) {
    // Wrapped in double, so the layer stays exact however far the camera or the world's time goes.
    const glm::dvec2 period = glm::dvec2(shared_.clouds->size()) * kCloudCellBlocks;
    const double x = inputs.cameraPosition.x + cloudDrift(inputs.ticks, shared_.clouds->size().x);
    view.clouds = shared_.clouds->id();
    view.cloudOrigin = glm::vec3(glm::mod(x, period.x), inputs.cameraPosition.y - kCloudBottom,
                                 glm::mod(inputs.cameraPosition.z, period.y));
  }
  return view;
}

// The sections and props the camera's passes draw.
void DeferredRenderer::cull(Frame& frame) const {
  const FrameView& view = frame.view;
  FrameStats& stats = frame.stats;
  frame.visible = sectionsInside(view.frustum, view.camera, frame.meshes, &stats.sectionsCulled);
  if (shared_.options.caveCulling) {
    const int radius = static_cast<int>(std::ceil(view.fogRange.y / 16.0f)) + 2;
    const SectionSet reached = reachableSections(frame.meshes, view.camera, view.frustum, radius);
    const auto hidden = std::remove_if(frame.visible.begin(), frame.visible.end(),
                                       [&](const VisibleSection& v) { return !reached.contains(v.pos); });
    stats.sectionsHidden = static_cast<int>(frame.visible.end() - hidden);
    frame.visible.erase(hidden, frame.visible.end());
  }
  stats.sectionsDrawn = static_cast<int>(frame.visible.size());
  if (frame.props) {
    frame.visibleProps = propsInside(view.frustum, view.camera, *frame.props);
    stats.propsDrawn = static_cast<int>(frame.visibleProps.size());
    stats.propsCulled = static_cast<int>(frame.props->instances().size() - frame.visibleProps.size());
  }
}

std::optional<ReflectionPixels> DeferredRenderer::readReflections() const {
  if (!reflected_) return std::nullopt;
  return reflection_.read();
}

std::size_t nonFinitePixels(const GBufferPixels& g) {
  std::size_t bad = 0;
  for (std::size_t p = 0; p < g.depth.size(); ++p) {
    bool finite = std::isfinite(g.depth[p]);
    for (int c = 0; c < 4; ++c)
      finite = finite && std::isfinite(g.scene[p][c]) && std::isfinite(g.normals[p][c]);
    bad += !finite;
  }
  return bad;
}

}  // namespace terrasol
