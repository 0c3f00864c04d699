#pragma once
// The passes that draw into the frame's target framebuffer: the final image (exposure, tone map,
// sRGB), a debug view of a G-buffer channel instead of it, and the targeted block's outline over
// either.

#include "render/gl/uniforms.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class FinalPass final : public RenderPass {
 public:
  FinalPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "final"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  PassShared& shared_;
  struct Final {
    Final() = default;
    explicit Final(const LinkedProgram& p) : exposure(p, "u_exposure") {}
    gl::Uniform<float> exposure;
  };
  struct Upscale {
    Upscale() = default;
    explicit Upscale(const LinkedProgram& p) : sceneScale(p, "u_sceneScale") {}
    gl::Uniform<glm::vec2> sceneScale;
  };
  gl::ProgramWith<Final> final_;
  gl::ProgramWith<Final> sharpened_;  // after TAA
  gl::ProgramWith<Upscale> upscale_;
  // At a render scale: the final image at the scene's size, then scaled up to the target.
  glm::ivec2 imageSize_{0};
  gl::Texture image_;
  gl::Framebuffer imageTarget_;
};

// FXAA over the final image, into the target (render.antialiasing "fxaa").
class FxaaPass final : public RenderPass {
 public:
  FxaaPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "fxaa"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;
  // The final image's texture and framebuffer at `size` (made on first use or a new size).
  std::pair<GLuint, GLuint> image(glm::ivec2 size);

 private:
  PassShared& shared_;
  gl::Program fxaa_;
  glm::ivec2 size_{0};
  gl::Texture image_;
  gl::Framebuffer framebuffer_;
};

// Writes the target without reading the lit scene, so the graph leaves out what only the final image needs.
class DebugViewPass final : public RenderPass {
 public:
  DebugViewPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "debug_view"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Debug {
    Debug() = default;
    explicit Debug(const LinkedProgram& p)
        : view(p, "u_view"),
          reflected(p, "u_reflected"),
          surfaceMarched(p, "u_surfaceMarched"),
          nearFar(p, "u_nearFar") {}
    gl::Uniform<int> view;
    gl::Uniform<bool> reflected, surfaceMarched;
    gl::Uniform<glm::vec2> nearFar;
  };
  PassShared& shared_;
  gl::ProgramWith<Debug> debug_;
};

// Edges of FrameInputs::outline, hidden where the G-buffer's depth has something nearer.
class OutlinePass final : public RenderPass {
 public:
  OutlinePass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "outline"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Outline {
    Outline() = default;
    explicit Outline(const LinkedProgram& p)
        : depthScale(p, "u_depthScale"),
          min(p, "u_min"),
          max(p, "u_max"),
          viewProjection(p, "u_viewProjection") {}
    gl::Uniform<glm::vec2> depthScale;
    gl::Uniform<glm::vec3> min, max;
    gl::Uniform<glm::mat4> viewProjection;
  };
  PassShared& shared_;
  gl::ProgramWith<Outline> outline_;
};

}  // namespace terrasol
