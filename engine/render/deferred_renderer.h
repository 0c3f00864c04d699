#pragma once
// The deferred pipeline, one frame at a time, as a graph of passes (render/frame_graph.h):
//   shadow       the light's depth (and translucent casters' colour) -> shadow map, kept across frames
//   geometry     opaque, then alpha-tested cutout -> G-buffer
//   lod          far terrain's tiles -> G-buffer
//   crack        the crack on a block being dug, multiplied into the G-buffer's albedo
//   lighting     LabPBR direct + ambient + block light + emission where something was drawn, sky elsewhere
//   reflection   screen-space reflections of smooth surfaces, with the sky where a ray finds nothing
//   translucent  water, glass, blended props: lit forward, blended over the lit scene
//   shafts       sunlight scattered by the height fog where the shadow map sees the sun
//   bloom        light spread from the scene into itself, energy-conserving
//   taa          the jittered scene resolved with its reprojected history at the target's size
//   final        exposure, tone map, sRGB -> the target framebuffer (or FXAA's image)
//   fxaa         the final image anti-aliased -> the target framebuffer
//   debug_view   a G-buffer channel -> the target instead of the final image
//   outline      the targeted block's edges over the target
// Each pass says when it has nothing to do; the graph leaves out what no pass that runs reads (a debug
// view needs no lighting, translucent pass or shadow map). Consumes meshes and the atlas; never sees
// the world. GL thread only.

#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <vector>

#include "assets/shader_source.h"
#include "render/frame_inputs.h"
#include "render/gbuffer.h"
#include "render/pass_clock.h"
#include "render/pass_shared.h"
#include "render/passes/bloom_pass.h"
#include "render/passes/crack_pass.h"
#include "render/passes/geometry_pass.h"
#include "render/passes/lighting_pass.h"
#include "render/passes/lod_pass.h"
#include "render/passes/output_passes.h"
#include "render/passes/reflection_pass.h"
#include "render/passes/shadow_pass.h"
#include "render/passes/shafts_pass.h"
#include "render/passes/taa_pass.h"
#include "render/passes/translucent_pass.h"
#include "render/section_meshes.h"
#include "render/world_renderer.h"

namespace terrasol {

class DeferredRenderer final : public WorldRenderer {
 public:
  DeferredRenderer(const ShaderPreprocessor& shaders, const Atlas& atlas, const TintPalette& tints,
                   const CloudMap& clouds, const RendererOptions& options = {});

  // Draws a frame into `framebuffer` (0 for a window) of `size`. With `timings`, each pass's time is
  // appended: from timer queries on a GPU, from glFinish and the wall clock on llvmpipe (whose timer
  // queries measure nothing useful).
  void render(const FrameInputs& frame, const SectionMeshes& meshes, GLuint framebuffer, glm::ivec2 size,
              std::vector<PassTiming>* timings = nullptr) override;

  // The targets of the last frame (for tests and reports), null before the first.
  const GBuffer* gbuffer() const { return gbuffer_ ? &*gbuffer_ : nullptr; }
  const FrameStats& lastFrame() const override { return stats_; }
  // The shader variants built: each program's name with the defines that chose it ("gbuffer+CUTOUT").
  const std::vector<std::string>& shaderVariants() const { return shared_.variants; }
  const GBufferContents& gbufferContents() const { return shared_.contents; }
  const FrameGeometry& lastGeometry() const override { return lastGeometry_; }
  // TAA's next frame starts afresh, from the jitter sequence's first offset (a camera path's start).
  void forgetHistory() override { taa_.forgetHistory(); }
  // The last frame's reflection march, read back (slow: for reports); none when the pass did not run.
  std::optional<ReflectionPixels> readReflections() const;
  // Pixels of TAA's last resolved frame holding NaN or Inf (read back: slow; 0 without TAA).
  std::size_t nonFiniteResolved() const { return taa_.nonFinitePixels(); }

 private:
  FrameView viewFor(const FrameInputs& inputs, glm::ivec2 size, glm::vec2 jitter) const;
  void cull(Frame& frame) const;

  PassShared shared_;  // before the passes: they build their programs into it
  GeometryPass geometry_;
  LodPass lod_;
  CrackPass crack_;
  LightingPass lighting_;
  ReflectionPass reflection_;
  TranslucentPass translucent_;
  ShadowPass shadow_;
  ShaftsPass shafts_;
  BloomPass bloom_;
  TaaPass taa_;
  FinalPass final_;
  FxaaPass fxaa_;
  DebugViewPass debug_;
  OutlinePass outline_;
  std::optional<GBuffer> gbuffer_;
  bool gpuTimer_;  // timer queries for pass timings (a real GPU); else glFinish and the wall clock
  FrameStats stats_;
  FrameGeometry lastGeometry_;
  bool reflected_ = false;  // the reflection pass ran in the last frame
};

// Pixels holding NaN or Inf in any float target (lit scene, normals, depth).
std::size_t nonFinitePixels(const GBufferPixels& gbuffer);

}  // namespace terrasol
