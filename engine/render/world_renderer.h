#pragma once
// What draws the world each frame: Terrasol's deferred renderer, or a shader pack's pipeline
// (pack_render/pack_renderer.h). Both draw the same section meshes with the same culling, so the game
// and scene renders hold one of each kind and switch between them from one frame to the next.

#include <glm/vec2.hpp>
#include <vector>

#include "render/frame_inputs.h"
#include "render/pass_clock.h"
#include "render/section_meshes.h"

namespace terrasol {

class WorldRenderer {
 public:
  WorldRenderer() = default;
  WorldRenderer(const WorldRenderer&) = delete;
  WorldRenderer& operator=(const WorldRenderer&) = delete;
  virtual ~WorldRenderer() = default;

  // Draws a frame into `framebuffer` (0 for a window) of `size`; with `timings`, each pass's time.
  virtual void render(const FrameInputs& frame, const SectionMeshes& meshes, GLuint framebuffer,
                      glm::ivec2 size, std::vector<PassTiming>* timings = nullptr) = 0;
  virtual const FrameStats& lastFrame() const = 0;
  // Where the last frame looked from, for reports that check it against the world.
  virtual const FrameGeometry& lastGeometry() const = 0;
  // The next frame does not follow on from the last (a camera path's start, a cut): what is carried
  // from frame to frame (TAA's history) starts afresh.
  virtual void forgetHistory() {}
};

}  // namespace terrasol
