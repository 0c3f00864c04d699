#pragma once
// What a frame is asked for (FrameInputs), the renderer's fixed choices (RendererOptions), and what
// the last frame did (FrameStats, FrameGeometry): the renderer's public types.

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/day_cycle.h"
#include "core/render_settings.h"
#include "render/props.h"

namespace terrasol {

class LodMeshes;

// A box in world coordinates (blocks).
struct WorldBox {
  glm::dvec3 min{0.0}, max{0.0};
};

// A block being dug: Minecraft's destroy_stage_<stage> texture darkens whatever surfaces lie in `cell`.
struct BlockCrack {
  WorldBox cell;
  int stage = 0;  // 0..9
};

// The camera under a liquid's surface (world/liquid.h): the surface's height and the sky light at
// the camera (0..1), which dims the colour the depths fade to.
struct UnderWater {
  double surfaceY = 0.0;
  float skyLight = 1.0f;
};

struct FrameInputs {
  glm::dvec3 cameraPosition{0.0};
  glm::dvec3 cameraLookAt{0.0, 0.0, -1.0};
  glm::dvec3 cameraUp{0.0, 1.0, 0.0};  // screen-up hint (camera paths roll it continuously)
  float fovDegrees = 70.0f;
  std::int64_t ticks = kNoon;    // world time
  float sunPathRotation = 0.0f;  // degrees
  float viewDistance = 64.0f;    // blocks: fog ends here
  DebugView debugView = DebugView::None;
  bool materialAo = true;  // LabPBR _n blue darkens ambient light
  // Moves the shadow map's centre as if the camera had moved, keeping the view: the flicker
  // measurement compares the same pixels (the same world points) under two map placements.
  glm::dvec3 shadowCentreOffset{0.0};
  // Keep last frame's shadow map while its centre, the meshes and (within 0.05 degrees) the light's
  // direction are unchanged: the game standing still pays no shadow pass. Off for measured renders.
  bool reuseShadowMap = false;
  // A second draw of a frame for a measure (the shadow report's moved map): TAA neither reads nor
  // moves on its history, so the frames after it are those of play.
  bool aside = false;
  // The targeted block: its edges are drawn over the image where nothing nearer hides them.
  std::optional<WorldBox> outline;
  std::optional<BlockCrack> crack;
  // glTF props drawn beside the blocks (null: none); the renderer was built for their PropNeeds.
  const Props* props = nullptr;
  // Far terrain beyond the sections (null: none); viewDistance then reaches its far edge.
  const LodMeshes* lod = nullptr;
  bool lodShadows = true;  // far terrain casts into the shadow map
  // Under water, the surface is seen from below and what lies beyond fades into the water's colour.
  std::optional<UnderWater> underWater;
  // Block and sky light (0..15) at the camera's cell: shader packs' eyeBrightness.
  glm::ivec2 eyeLight{0, 15};
  // The G-buffer, lighting and translucent passes draw at this fraction of the target's size (0.25..1),
  // and the final pass scales the picture up to it (render/dynamic_resolution.h moves it in the game).
  // Debug views always draw at 1.
  float renderScale = 1.0f;
};

// The size the scene is drawn at for a target of `size` and a render scale (clamped to 0.25..1).
glm::ivec2 scaledRenderSize(glm::ivec2 size, float scale);

// Choices that pick shader variants, fixed for the renderer's life.
struct RendererOptions {
  bool ggxSpecular = false;   // GGX/Smith instead of energy-conserving Blinn-Phong
  bool caveCulling = true;    // leave out sections hidden behind solid ground (render/cave_culling.h)
  bool cullFacesAway = true;  // leave out face groups turned away from the camera for a whole section
  // The frame graph leaves out passes whose output no pass that runs reads, and the translucent pass
  // with nothing translucent in view (off: every pass that can run does, for tests of that rule).
  bool cullPasses = true;
  // Leave out shadow casters whose shadow can fall on nothing in view (render/shadow_receivers.h).
  bool shadowCasterCulling = true;
  // With no _n (_s) in any loaded pack, the shaders use LabPBR's default instead of sampling it.
  bool leaveOutAbsentMaps = true;
  ShadowSettings shadow;
  ReflectionSettings reflections;
  Antialiasing antialiasing = Antialiasing::None;
  WaterSettings water;
  BloomSettings bloom;
  CloudSettings clouds;
  FogSettings fog;
  ShaftSettings shafts;
  PropNeeds props;  // what the props to be drawn need: no prop variant is built for none
};

// Where the last frame looked from, for reports that check it against the world.
struct FrameGeometry {
  glm::dvec3 camera{0.0};
  glm::mat4 viewProjection{1.0f};  // camera-relative
  glm::mat4 inverseViewProjection{1.0f};
  glm::vec3 toLight{0.0f, 1.0f, 0.0f};  // the shadow-casting light
  bool shadowMapShown = false;          // the lit passes read a shadow map (drawn this frame, or kept)
  float shadowTexelWorld = 0.0f;        // blocks per texel of the unwarped shadow map (its first layer)
};

// What the last frame did, for reports.
struct FrameStats {
  int sectionsDrawn = 0, sectionsCulled = 0;  // 16x16x16 sections with a mesh, inside / outside the frustum
  int sectionsHidden = 0;                     // inside the frustum, but cave culling left them out
  int shadowCasters = 0;                      // sections drawn into the shadow map
  int shadowCastersHidden = 0;                // inside the light's box, but no ray of it reaches them
  int shadowCastersOffView = 0;               // lit, but their shadow falls on nothing in view
  int shadowSlices = 0;                       // of update_frames drawn this frame: 0 kept, all a whole draw
  std::int64_t quadsDrawn = 0;                // by the camera's passes (geometry, translucent)
  std::int64_t quadsFacingAway = 0;           // opaque and cutout quads left out: their face group faced away
  int propsDrawn = 0, propsCulled = 0;        // placed props inside / outside the frustum
  int propShadowCasters = 0;                  // props drawn into the shadow map (per layer)
  int lodTilesDrawn = 0, lodTilesCulled = 0;  // far terrain's tiles inside / outside the frustum
  std::int64_t lodTrianglesDrawn = 0;
  int lodShadowCasters = 0;  // far terrain's tiles drawn into the shadow map (per layer)
  struct Skipped {
    std::string pass, why;
  };
  std::vector<Skipped> passesSkipped;
};

}  // namespace terrasol
