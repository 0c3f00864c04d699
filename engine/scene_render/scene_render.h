#pragma once
// A scene file rendered frame by frame, with a current GL context: what terrasol-render and the scene
// tests share. Loads the packs and the atlas, builds and lights the world, meshes it, then draws the
// frames of its camera path in order (edits keyed to frames apply as the path reaches them).

#include <memory>
#include <optional>
#include <vector>

#include "assets/image.h"
#include "render/deferred_renderer.h"
#include "render/dynamic_resolution.h"
#include "scene/scene_file.h"
#include "world/world.h"

namespace terrasol {

class PackRenderer;

inline constexpr int kTaaWarmFrames = 16;

struct SceneRenderStats {
  std::size_t sections = 0, quads = 0;
  double loadMs = 0.0, worldMs = 0.0;  // packs and atlas; world generation, light and meshing
  std::vector<PackProblem> problems;   // from the packs: warnings, never fatal
  std::string shaderpackError;         // render.shaderpack failed to load: Terrasol's pipeline draws
};

// Far terrain as the last frame drew it (render.lod).
struct SceneLodStats {
  int tiles = 0, levels = 0;
  std::size_t triangles = 0, cpuBytes = 0, gpuBytes = 0;
  double buildMs = 0.0;  // the longest wait for a frame's tiles: the first frame's, which builds them all
};

struct RenderedFrame {
  Image image;
  std::vector<PassTiming> timings;  // when asked for: glFinish after each pass
  FrameStats stats;
  std::size_t nanPixels = 0;                    // when asked for
  GBufferPixels pixels;                         // with checkNan or readBack
  std::optional<ReflectionPixels> reflections;  // with readBack, when the reflection pass ran
  FrameGeometry geometry;
};

struct FrameRequest {
  bool timed = false;
  bool checkNan = false;
  bool readBack = false;               // keep the G-buffer's pixels (shadow-error report)
  glm::dvec3 shadowCentreOffset{0.0};  // moves the shadow map as if the camera had moved (flicker)
  std::optional<DebugView> debugView;  // overrides the scene's
  bool reuseShadowMap = false;         // FrameInputs::reuseShadowMap
  bool aside = false;                  // FrameInputs::aside
  std::optional<float> renderScale;    // overrides the scene's (the far terrain report's yardstick)
  std::optional<BlockCrack> crack;     // FrameInputs::crack
};

// The scene with full detail out to its far terrain's edge and no far terrain: far terrain's truth.
SceneFile lodTruthScene(const SceneFile& scene);
// The truth is made only out to this many chunks: each costs some 300 KB, so 32 takes ~1.3 GB and 64
// five times that.
inline constexpr int kMaxLodTruthChunks = 32;

class SceneRenderer {
 public:
  // Everything but the frames. Throws Error naming the scene key for bad scene content.
  explicit SceneRenderer(const SceneFile& scene);
  ~SceneRenderer();

  int frames() const { return scene_.frameCount(); }
  // Frames must come in order (0, 1, ...; repeating the last one is fine): edits keyed to frames
  // change the world as the path passes them. Frame 0 starts the path afresh: with TAA, its history is
  // first warmed by drawing frame 0 over the jitter sequence (up to kTaaWarmFrames), so every run of a
  // scene gives the same pixels; later frames carry the history on, as in play.
  RenderedFrame renderFrame(int frame, const FrameRequest& request = {});

  // Draws frame `frame` straight into `framebuffer` (0: a window's back buffer) of `size`.
  void draw(int frame, GLuint framebuffer, glm::ivec2 size);

  // Frame 0; with `timings` it is drawn twice and the second is timed (the first pays for warm-up).
  Image render(std::vector<PassTiming>* timings = nullptr);
  Image render(DebugView debugView);

  const SceneRenderStats& stats() const { return stats_; }
  // With render.lod on: its tiles and their memory.
  std::optional<SceneLodStats> lodStats() const;
  const SceneFile& scene() const { return scene_; }
  const terrasol::World& world() const;
  DeferredRenderer& renderer();
  // The shader pack drawing in the renderer's place (render.shaderpack), or null.
  const PackRenderer* shaderPack() const;

 private:
  struct Gpu;
  struct World;
  FrameInputs inputsFor(int frame) const;
  void advanceTo(int frame);  // edits keyed to frames up to `frame`, their meshes and the props' light
  WorldRenderer& drawing();   // the shader pack when there is one, else the deferred renderer
  void warmHistory(const FrameInputs& inputs);

  SceneFile scene_;
  DebugView debugView_;
  SceneRenderStats stats_;
  std::unique_ptr<World> world_;
  std::unique_ptr<Gpu> gpu_;
  DynamicResolution resolution_;  // with render.target_fps: the scale of the next frame
};

}  // namespace terrasol
