#pragma once
// Temporal anti-aliasing and upscaling (render.antialiasing "taa"): the scene, drawn with a jittered
// projection at the render scale's size, is resolved at the target's size against the last frame's
// result, reprojected by depth and the camera's motion, clipped to the neighbourhood of this frame's
// samples and rejected where it was hidden. Keeps its history across frames.

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "render/gl/uniforms.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class TaaPass final : public RenderPass {
 public:
  TaaPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "taa"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

  // The next frame starts without history (a cut, a debug view in between, a path's first frame).
  void forgetHistory() { historyValid_ = false; }
  // The index of the next frame in the jitter sequence: from 0 after forgetHistory.
  int nextJitterFrame() const { return historyValid_ ? jitterFrame_ : 0; }
  // The last frame's (an aside draws with it, so its pixels are that frame's).
  int lastJitterFrame() const { return historyValid_ ? jitterFrame_ - 1 : 0; }
  // Pixels of the last resolved frame holding NaN or Inf (read back: slow; 0 without history).
  std::size_t nonFinitePixels() const;

 private:
  struct Resolve {
    Resolve() = default;
    explicit Resolve(const LinkedProgram& p)
        : inverseViewProjection(p, "u_inverseViewProjection"),
          reprojection(p, "u_reprojection"),
          cameraMotion(p, "u_cameraMotion"),
          jitter(p, "u_jitter"),
          sceneScale(p, "u_sceneScale"),
          historyValid(p, "u_historyValid"),
          reactive(p, "u_reactive") {}
    gl::Uniform<glm::mat4> inverseViewProjection, reprojection;
    gl::Uniform<glm::vec3> cameraMotion;
    gl::Uniform<glm::vec2> jitter, sceneScale;
    gl::Uniform<bool> historyValid, reactive;
  };
  void realize(glm::ivec2 size);

  PassShared& shared_;
  gl::ProgramWith<Resolve> resolve_;
  glm::ivec2 size_{0};
  gl::Texture history_[2];  // rgb: the resolved colour (linear HDR); a: the surface's distance
  gl::Framebuffer target_[2];
  int current_ = 0;  // the one written this frame
  bool historyValid_ = false;
  int jitterFrame_ = 0;
  glm::mat4 lastViewProjection_{1.0f};  // unjittered
  glm::dvec3 lastCamera_{0.0};
};

}  // namespace terrasol
