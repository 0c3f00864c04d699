#pragma once
// A scene file rendered to an image, with a current GL context: what terrasol-render and the scene
// tests share. Loads the packs and the atlas, builds and lights the world, meshes it, draws a frame.

#include <vector>

#include "assets/image.h"
#include "render/deferred_renderer.h"
#include "scene/scene_file.h"

namespace terrasol {

struct SceneRenderStats {
  std::size_t sections = 0, quads = 0;
  double loadMs = 0.0, worldMs = 0.0;  // packs and atlas; world generation, light and meshing
  std::vector<PackProblem> problems;   // from the packs: warnings, never fatal
};

class SceneRenderer {
 public:
  // Everything but the frame itself. Throws Error naming the scene key for bad scene content.
  explicit SceneRenderer(const SceneFile& scene);
  ~SceneRenderer();

  // Draws the scene (with `debugView` overriding the scene's own) and reads the image back. With
  // `timings`, one more frame is drawn and timed pass by pass (the first pays for warm-up).
  Image render(std::vector<PassTiming>* timings = nullptr);
  Image render(DebugView debugView);

  const SceneRenderStats& stats() const { return stats_; }
  const FrameInputs& frame() const { return frame_; }
  DeferredRenderer& renderer();

 private:
  struct Gpu;
  SceneFile scene_;
  FrameInputs frame_;
  SceneRenderStats stats_;
  std::unique_ptr<Gpu> gpu_;
};

// The DebugView of a scene's "render.debug_view" name; throws Error naming the key.
DebugView debugViewOf(const SceneFile& scene);

}  // namespace terrasol
