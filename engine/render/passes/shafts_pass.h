#pragma once
// Light shafts (render.shafts): the sunlight the height fog's medium scatters towards the camera where
// the shadow map sees the sun, marched at a fraction of the frame's size (shafts.frag) and added to the
// lit scene, scaled up bilinearly (shafts_composite.frag). Needs the shadow map and the fog.

#include <glm/vec2.hpp>

#include "render/frame_uniforms.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"

namespace terrasol {

class ShaftsPass final : public RenderPass {
 public:
  ShaftsPass(const VariantBuilder& build, PassShared& shared);
  const char* name() const override { return "shafts"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

 private:
  struct March {
    March() = default;
    explicit March(const LinkedProgram& p)
        : sky(p),
          shadow(p),
          inverseViewProjection(p, "u_inverseViewProjection"),
          toLight(p, "u_toLight"),
          lightColor(p, "u_lightColor"),
          distance(p, "u_shaftDistance"),
          noiseOffset(p, "u_noiseOffset") {}
    SkyUniforms sky;
    ShadowUniforms shadow;
    gl::Uniform<glm::mat4> inverseViewProjection;
    gl::Uniform<glm::vec3> toLight, lightColor;
    gl::Uniform<float> distance;
    gl::Uniform<glm::vec2> noiseOffset;
  };
  void realize(glm::ivec2 size);

  PassShared& shared_;
  gl::ProgramWith<March> march_;
  struct Composite {
    Composite() = default;
    explicit Composite(const LinkedProgram& p) : scale(p, "u_scale") {}
    gl::Uniform<glm::vec2> scale;
  };
  gl::ProgramWith<Composite> composite_;
  glm::ivec2 size_{0};
  gl::Texture shafts_;
  gl::Framebuffer target_;
  int frameIndex_ = 0;
};

}  // namespace terrasol
