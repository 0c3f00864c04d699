#pragma once
// The deferred pipeline, one frame at a time:
//   geometry (opaque, then alpha-tested cutout) -> G-buffer
//   lighting (full screen: LabPBR direct + ambient + block light + emission), sky where nothing was drawn
//   translucent (water, glass: lit forward, blended; left out when none is loaded)
//   final (exposure, tone map, sRGB) -> the target framebuffer
// A debug view replaces lighting, translucent and final with one pass showing a G-buffer channel.
// Consumes meshes and the atlas; never sees the world. GL thread only.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "assets/shader_source.h"
#include "render/block_textures.h"
#include "render/cave_culling.h"
#include "render/frustum.h"
#include "render/gbuffer.h"
#include "render/pass_clock.h"
#include "render/props.h"
#include "render/section_meshes.h"
#include "render/shadow_map.h"
#include "render/shadow_receivers.h"

namespace terrasol {

// G-buffer channels the debug views show, in this order ("none" = the lit image).
enum class DebugView { None, Albedo, Normal, VertexNormal, Specular, Lightmap, Depth, Ao, Emission };
inline constexpr const char* kDebugViewNames[] = {"none",     "albedo", "normal", "vertex_normal", "specular",
                                                  "lightmap", "depth",  "ao",     "emission"};

// A box in world coordinates (blocks).
struct WorldBox {
  glm::dvec3 min{0.0}, max{0.0};
};

struct FrameInputs {
  glm::dvec3 cameraPosition{0.0};
  glm::dvec3 cameraLookAt{0.0, 0.0, -1.0};
  glm::dvec3 cameraUp{0.0, 1.0, 0.0};  // screen-up hint (camera paths roll it continuously)
  float fovDegrees = 70.0f;
  std::int64_t ticks = 6000;      // world time
  float sunPathRotation = 0.0f;   // degrees
  float viewDistance = 64.0f;     // blocks: fog ends here
  DebugView debugView = DebugView::None;
  bool materialAo = true;         // LabPBR _n blue darkens ambient light
  // Moves the shadow map's centre as if the camera had moved, keeping the view: the flicker
  // measurement compares the same pixels (the same world points) under two map placements.
  glm::dvec3 shadowCentreOffset{0.0};
  // Keep last frame's shadow map while its centre, the meshes and (within 0.05 degrees) the light's
  // direction are unchanged: the game standing still pays no shadow pass. Off for measured renders.
  bool reuseShadowMap = false;
  // The targeted block: its edges are drawn over the image where nothing nearer hides them.
  std::optional<WorldBox> outline;
  // glTF props drawn beside the blocks (null: none); the renderer was built for their PropNeeds.
  const Props* props = nullptr;
};

// Choices that pick shader variants, fixed for the renderer's life.
struct RendererOptions {
  bool ggxSpecular = false;  // GGX/Smith instead of energy-conserving Blinn-Phong
  bool caveCulling = true;   // leave out sections hidden behind solid ground (render/cave_culling.h)
  bool cullFacesAway = true;  // leave out face groups turned away from the camera for a whole section
  // Leave out shadow casters whose shadow can fall on nothing in view (render/shadow_receivers.h).
  bool shadowCasterCulling = true;
  // With no _n (_s) in any loaded pack, the shaders use LabPBR's default instead of sampling it.
  bool leaveOutAbsentMaps = true;
  ShadowSettings shadow;
  PropNeeds props;  // what the props to be drawn need: no prop variant is built for none
};

// Where the last frame looked from, for reports that check it against the world.
struct FrameGeometry {
  glm::dvec3 camera{0.0};
  glm::mat4 viewProjection{1.0f};         // camera-relative
  glm::mat4 inverseViewProjection{1.0f};
  glm::vec3 toLight{0.0f, 1.0f, 0.0f};    // the shadow-casting light
  bool shadowLive = false;                // the shadow pass ran
  float shadowTexelWorld = 0.0f;          // blocks per texel of the unwarped shadow map (its first layer)
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
  struct Skipped {
    std::string pass, why;
  };
  std::vector<Skipped> passesSkipped;
};

class DeferredRenderer {
 public:
  // How far, as a fraction of the shadow distance, a kept map's centre may fall behind the camera's
  // before it is redrawn whole; spread rebuilds are paced to land within it.
  static constexpr double kKeptShadowReach = 0.25;

  DeferredRenderer(const ShaderPreprocessor& shaders, const Atlas& atlas, const BiomeTints& tints,
                   const RendererOptions& options = {});

  // Draws a frame into `framebuffer` (0 for a window) of `size`. With `timings`, each pass's time is
  // appended: from timer queries on a GPU, from glFinish and the wall clock on llvmpipe (whose timer
  // queries measure nothing useful).
  void render(const FrameInputs& frame, const SectionMeshes& meshes, GLuint framebuffer, glm::ivec2 size,
              std::vector<PassTiming>* timings = nullptr);

  // The targets of the last frame (for tests and reports), null before the first.
  const GBuffer* gbuffer() const { return gbuffer_ ? &*gbuffer_ : nullptr; }
  const FrameStats& lastFrame() const { return stats_; }
  // The block atlas's albedo (sRGB, with mipmaps): for the HUD's block icons.
  GLuint atlasAlbedo() const { return textures_.atlas().albedo(); }
  // The shader variants built: each program's name with the defines that chose it ("gbuffer+CUTOUT").
  const std::vector<std::string>& shaderVariants() const { return variants_; }
  const GBufferContents& gbufferContents() const { return contents_; }
  const FrameGeometry& lastGeometry() const { return lastGeometry_; }

 private:
  struct View;
  struct Visible {
    const SectionMeshes::Section* section;
    glm::vec3 offset;  // section corner minus camera
    SectionPos pos;
  };
  void cull(const View& view, const SectionMeshes& meshes);
  void geometryPass(const View& view, const SectionMeshes& meshes);
  void lightingPass(const View& view);
  void translucentPass(const View& view, const SectionMeshes& meshes);
  void finalPass(GLuint framebuffer, glm::ivec2 size);
  void debugPass(const View& view, GLuint framebuffer, glm::ivec2 size);
  void outlinePass(const View& view, const WorldBox& box, GLuint framebuffer, glm::ivec2 size);
  // How drawSections orders and trims: sections by their centre's distance from the camera, or (with
  // a non-zero `axis`) by how far along `axis` it lies, nearest first so the depth test can reject
  // hidden fragments before shading. `cullFacesAway` (passes that cull back faces) leaves out face
  // groups turned away from the camera for a whole section before any vertex is shaded; `countQuads`
  // adds what is drawn and left out to the frame's stats (the camera's passes).
  enum class DrawOrder { NearestFirst, FarthestFirst };
  struct SectionDraw {
    DrawOrder order = DrawOrder::NearestFirst;
    glm::vec3 axis{0.0f};
    bool cullFacesAway = false;
    bool countQuads = false;
    SectionMeshes::View view = SectionMeshes::View::Camera;
  };
  void drawSections(GLuint program, const std::vector<Visible>& sections, const SectionMeshes& meshes,
                    MeshLayer layer, const SectionDraw& how);
  // Returns false when the last frame's map was kept (FrameInputs::reuseShadowMap).
  bool shadowPass(const View& view, const SectionMeshes& meshes, bool mayReuse);
  void rebaseShadowViews(const View& view);
  void setWarpUniforms(GLuint program) const;
  void setShadowUniforms(GLuint program, bool live) const;
  // The sections with a mesh whose box is inside `planes` (camera-relative); counts the others.
  static std::vector<Visible> sectionsInside(const FrustumPlanes& planes, glm::dvec3 camera,
                                             const SectionMeshes& meshes, int* outside = nullptr);
  glm::dvec3 mapCentre(glm::dvec3 wanted);
  std::size_t visibleQuads(MeshLayer layer) const;
  void setLightingUniforms(GLuint program, const View& view) const;
  void setSkyUniforms(GLuint program, const View& view) const;
  // Props (prop_pass.cpp): the instances inside `planes`, and a draw of the meshes whose material has
  // alpha mode `mode` (blended ones farthest first).
  static std::vector<int> propsInside(const FrustumPlanes& planes, glm::dvec3 camera, const Props& props);
  void drawProps(GLuint program, const Props& props, const std::vector<int>& instances, glm::dvec3 camera,
                 AlphaMode mode, bool cullBackFaces) const;
  bool visibleBlendedProps() const;
  void buildPropPrograms(const ShaderPreprocessor& shaders);

  std::vector<std::string> variants_;  // before the programs: building each one names it here
  GBufferContents contents_;           // likewise: the programs are built for it
  gl::Program geometry_, cutout_, lighting_, sky_, translucent_, shadow_, shadowCutout_, shadowTranslucent_,
      final_, debug_, outline_;
  // Props' variants, each built only when a placed prop needs it (RendererOptions::props).
  gl::Program propGeometry_, propCutout_, propTranslucent_, propShadow_, propShadowCutout_, propShadowTranslucent_;
  BlockTextures textures_;
  gl::VertexArray empty_;  // full-screen passes make their vertices from gl_VertexID
  std::optional<GBuffer> gbuffer_;
  RendererOptions options_;
  ShadowMap shadowMap_;
  std::array<ShadowView, kMaxShadowCascades> shadowViews_{};  // this frame's, one per layer
  std::optional<glm::dvec3> warpCentre_;  // where the warped map is centred, kept between frames
  struct ShadowKey {                      // what the maps were drawn for
    glm::dvec3 centre{0.0};
    glm::vec3 toLight{0.0f};
    std::uint64_t meshes = 0;
    std::uint64_t props = 0;
    bool valid = false;
    std::optional<ShadowReceivers> receivers;  // what the casters were chosen for; none: every caster
  } shadowKey_;
  struct ShadowBuild {                    // a map being rebuilt a slice a frame (update_frames > 1)
    ShadowKey key;
    int slice = 0;
    std::optional<SectionSet> lit;  // walked once for all slices
  };
  std::optional<ShadowBuild> build_;
  ShadowMap building_;
  std::optional<glm::dvec3> lastWantedCentre_;  // last frame's, for how fast the map falls behind
  std::optional<SectionSet> litSections(const ShadowKey& key, const SectionMeshes& meshes) const;
  struct ShadowSlices {
    int first, count, of;
  };
  void drawShadowCasters(ShadowMap& map, const ShadowKey& key, const std::optional<SectionSet>& lit,
                         const View& view, const SectionMeshes& meshes, ShadowSlices slices);
  bool gpuTimer_;  // timer queries for pass timings (a real GPU); else glFinish and the wall clock
  std::vector<Visible> visible_;  // this frame's sections inside the frustum
  std::vector<int> visibleProps_;  // this frame's prop instances inside the frustum
  const Props* props_ = nullptr;   // this frame's (FrameInputs::props)
  FrameStats stats_;
  FrameGeometry lastGeometry_;
};

// Pixels holding NaN or Inf in any float target (lit scene, normals, depth).
std::size_t nonFinitePixels(const GBufferPixels& gbuffer);

}  // namespace terrasol
