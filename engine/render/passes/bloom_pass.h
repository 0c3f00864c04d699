#pragma once
// Bloom (render.bloom): the lit scene halved and halved again down a chain of levels by 2 x 2 box
// averages, summed back up level by level, and blended into the scene as (1 - strength) x scene +
// strength x the levels' mean. Each level carries the frame's whole energy, so the blend moves light
// without adding any; there is no threshold, so nothing pops in as it brightens.

#include <glm/vec2.hpp>
#include <vector>

#include "render/gl/uniforms.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class BloomPass final : public RenderPass {
 public:
  BloomPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "bloom"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct Level {
    glm::ivec2 size;
    gl::Texture down, up;  // the scene averaged to this size; this level and those below summed
    gl::Framebuffer downTarget, upTarget;
  };
  struct Composite {
    Composite() = default;
    explicit Composite(const LinkedProgram& p) : strength(p, "u_strength"), weights(p, "u_weights") {}
    gl::Uniform<float> strength, weights;
  };
  void realize(glm::ivec2 sceneSize);
  bool brightInView(const Frame& frame) const;
  void draw(GLuint program, GLuint framebuffer, glm::ivec2 size) const;

  PassShared& shared_;
  LinkedProgram down_;
  struct Up {
    Up() = default;
    explicit Up(const LinkedProgram& p) : spread(p, "u_spread") {}
    gl::Uniform<float> spread;
  };
  gl::ProgramWith<Up> up_;
  gl::ProgramWith<Composite> composite_;
  glm::ivec2 sceneSize_{0};
  std::vector<Level> levels_;  // half the scene's size first
};

}  // namespace terrasol
