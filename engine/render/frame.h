#pragma once
// One frame as the renderer's passes share it: the view, what is visible, the targets, the shadow
// lookup and the stats the passes add to. Built by DeferredRenderer::render; internal to engine/render.

#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "core/day_cycle.h"
#include "core/lightmap.h"
#include "render/frame_graph.h"
#include "render/frame_inputs.h"
#include "render/frustum.h"
#include "render/gbuffer.h"
#include "render/section_meshes.h"
#include "render/shadow_map.h"
#include "render/shadow_receivers.h"
#include "render/visible_section.h"

namespace terrasol {

struct FrameView {
  glm::dvec3 camera{0.0};
  glm::mat4 viewProjection{1.0f};  // camera-relative, jittered with TAA on
  glm::mat4 inverseViewProjection{1.0f};
  glm::mat4 unjittered{1.0f};  // viewProjection without the jitter (TAA's reprojection, the outline)
  glm::vec2 jitter{0.0f};      // TAA's offset this frame, in scene pixels
  FrustumPlanes frustum{};     // camera-relative
  glm::vec2 nearFar{0.0f};
  glm::vec2 fogRange{0.0f};
  DayState day;
  LightmapColours lightmap;
  bool materialAo = true;
  bool lightUp = false;  // shadows are on and the shadow-casting light is above the horizon
  glm::dvec3 shadowCentreOffset{0.0};
  glm::dvec3 forward{0.0, 0.0, -1.0};  // unit view direction
  bool underWater = false;
  float waterTop = 0.0f;        // under water: the surface's height above the camera
  glm::vec3 waterFog{0.0f};     // under water: the colour the depths fade to (linear)
  ViewCone cone;                // the view's receivers, for the shadow pass
  GLuint clouds = 0;            // the cloud layer's map (0: no clouds)
  glm::vec3 cloudOrigin{0.0f};  // the camera in the layer's space (lib/clouds.glsl)
  glm::vec2 heightFog{0.0f};    // the height fog's extinction per block at the camera, its falloff (blocks)
  glm::vec3 heightFogColour{0.0f};  // the sky's light it scatters, as much as reaches the camera
};

// What the lighting and translucent passes read of the shadow map (the shadow pass's).
struct ShadowLookup {
  const ShadowSettings* settings = nullptr;
  const ShadowMap* map = nullptr;
  const std::array<ShadowView, kMaxShadowCascades>* views = nullptr;  // this frame's, one per layer
};

// The frame graph's names for the frame's resources.
struct FrameResources {
  FrameGraph::Resource gbuffer, scene, shadowMap, target;
  FrameGraph::Resource reflections;  // the reflection pass's own targets (its debug views read them)
  FrameGraph::Resource image;        // the final image before FXAA (when it is on)
  FrameGraph::Resource resolved;     // TAA's output: the scene at the target's size
};

// The reflection pass's targets this frame: from opaque surfaces (for the debug views), and from
// water and glass (for the translucent pass); 0 where that part did not run.
struct ReflectionTargets {
  GLuint added = 0, hits = 0;
  GLuint surfaceReflected = 0, surfaceHits = 0;
};

struct Frame {
  Frame(const FrameInputs& inputs, const SectionMeshes& meshes, FrameStats& stats)
      : inputs(inputs), meshes(meshes), stats(stats) {}

  const FrameInputs& inputs;
  const SectionMeshes& meshes;
  FrameStats& stats;
  FrameView view;
  const Props* props = nullptr;         // null: none to draw
  std::vector<VisibleSection> visible;  // inside the frustum, not hidden by cave culling
  std::vector<int> visibleProps;        // prop instances inside the frustum
  FrameResources resources{};
  GBuffer* gbuffer = nullptr;  // realized by the graph before the first pass that needs it
  GLuint target = 0;           // the framebuffer drawn into (0: a window)
  // Where the final pass draws: the target, or with anti-aliasing on the image the FXAA pass reads.
  GLuint finalTarget = 0;
  GLuint finalImage = 0;     // that image's texture (0: none)
  bool temporal = false;     // TAA resolves the scene: the final pass reads `resolved`
  GLuint resolved = 0;       // TAA's output (linear HDR at the target's size), once it has run
  GLuint reactive = 0;       // where the translucent pass drew what changes by itself (water), for TAA
  glm::ivec2 size{0};        // the scene's: the G-buffer's and every pass's before the final one
  glm::ivec2 targetSize{0};  // the target's: the final pass scales the scene up to it
  ShadowLookup shadow;
  ReflectionTargets reflections;
  // The shadow pass drew or kept the map this frame. (A frame whose passes never read the map, a debug
  // view, does not move the schedule on; the next frame then sees the camera's pace over both.)
  bool shadowDrawn = false;
};

}  // namespace terrasol
