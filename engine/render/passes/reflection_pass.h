#pragma once
// Screen-space reflections, marched at render.reflections.resolution_scale of the frame into targets
// of its own. Smooth opaque and cutout surfaces (shaders/reflection.frag): a mask (depth 0 where a
// surface is smooth enough), the march (only there, by the depth test), then the result filtered up
// and added to the lit scene where something was drawn. Water and glass
// (shaders/surface_reflection.frag): the opaque depth scaled down, a depth-only draw of the
// translucent quads, then the march over the nearest of them; the translucent pass weighs what it
// saw by Fresnel. Each part is left out where nothing in view needs it: no smooth texture on the
// opaque sections in view, no translucent quad in view.

#include <glm/vec4.hpp>
#include <vector>

#include "render/frame_uniforms.h"
#include "render/pass_shared.h"
#include "render/render_pass.h"
#include "render/section_draw.h"

namespace terrasol {

// The last march read back (slow: for the reflection-error report), at the pass's own resolution,
// rows bottom first.
struct ReflectionPixels {
  glm::ivec2 size{0};
  std::vector<glm::vec4> added;  // rgb added to the lit scene; a: 1 where the ray hit
  std::vector<glm::vec4> hits;   // xy: hit screen uv; z: 1 hit, 0 marched without a hit, -1 not
                                 // marched; w: the surface's depth along the view
  // The march from water and glass, where it ran: what the ray saw (rgb; a: 1 hit), where (as `hits`),
  // and from which surface (xyz: the normal; w: its sky light).
  std::vector<glm::vec4> surfaceReflected, surfaceHits, surfaceNormals;
};

class ReflectionPass final : public RenderPass {
 public:
  ReflectionPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "reflection"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

  ReflectionPixels read() const;

 private:
  bool smoothInView(const Frame& frame) const;
  void ensureTargets(glm::ivec2 size);
  void setUniforms(const Frame& frame) const;
  void marchFromOpaque(Frame& frame);
  void marchFromSurfaces(Frame& frame);

  struct Mask {
    Mask() = default;
    explicit Mask(const LinkedProgram& p)
        : minSmoothness(p, "u_minSmoothness"), targetSize(p, "u_targetSize") {}
    gl::Uniform<float> minSmoothness;
    gl::Uniform<glm::ivec2> targetSize;  // the reflection target's, which samples the G-buffer
  };
  struct March {
    March() = default;
    explicit March(const LinkedProgram& p) : lighting(p), sky(p), ssr(p) {}
    LightingUniforms lighting;
    SkyUniforms sky;
    SsrUniforms ssr;
  };
  struct OpaqueMarch {
    OpaqueMarch() = default;
    explicit OpaqueMarch(const LinkedProgram& p) : march(p), targetSize(p, "u_targetSize") {}
    March march;
    gl::Uniform<glm::ivec2> targetSize;
  };
  struct Composite {
    Composite() = default;
    explicit Composite(const LinkedProgram& p)
        : minSmoothness(p, "u_minSmoothness"), nearFar(p, "u_nearFar") {}
    gl::Uniform<float> minSmoothness;
    gl::Uniform<glm::vec2> nearFar;
  };
  struct SurfaceDepth {
    SurfaceDepth() = default;
    explicit SurfaceDepth(const LinkedProgram& p) : section(p), viewProjection(p, "u_viewProjection") {}
    SectionUniforms section;
    gl::Uniform<glm::mat4> viewProjection;
  };
  struct SurfaceMarch {
    SurfaceMarch() = default;
    explicit SurfaceMarch(const LinkedProgram& p) : section(p), march(p), waves(p) {}
    SectionUniforms section;
    March march;
    WaveUniforms waves;
  };

  PassShared& shared_;
  // Only when reflections are on.
  gl::ProgramWith<Mask> mask_;  // opaque surfaces
  gl::ProgramWith<OpaqueMarch> march_;
  gl::ProgramWith<Composite> composite_;
  LinkedProgram depthCopy_;  // water and glass
  gl::ProgramWith<SurfaceDepth> surfaceDepth_;
  gl::ProgramWith<SurfaceMarch> surfaceMarch_;
  bool opaque_ = false, surfaces_ = false;  // this frame's parts
  glm::ivec2 size_{0};
  gl::Texture colour_;  // RGBA16F: rgb added to the scene, a: 1 where the ray hit something on screen
  gl::Texture hits_;    // RGBA32F: where each ray hit (ReflectionPixels::hits)
  gl::Texture surfaceReflected_, surfaceHits_, surfaceNormals_;  // ReflectionPixels' surface*
  gl::Renderbuffer depth_;
  gl::Framebuffer target_, surfaceTarget_;
};

}  // namespace terrasol
