#pragma once
// The light's view, a layer per cascade, into the shadow map the lit passes read. Casters are far
// terrain's tiles and the sections inside a layer's box, less those no ray of the light reaches
// (cave_culling.h) and those whose shadow falls on nothing in view (shadow_receivers.h); opaque, then
// alpha-tested, then translucent casters into their own depth and colour. When the map is drawn, kept or
// rebuilt a slice a frame is ShadowSchedule's decision; a spread rebuild draws into a second map, swapped in
// when complete.

#include <array>
#include <optional>

#include "render/cave_culling.h"
#include "render/frame_uniforms.h"
#include "render/lod_draw.h"
#include "render/pass_shared.h"
#include "render/prop_draw.h"
#include "render/render_pass.h"
#include "render/section_draw.h"
#include "render/shadow_map.h"
#include "render/shadow_schedule.h"

namespace terrasol {

class ShadowPass final : public RenderPass {
 public:
  ShadowPass(const VariantBuilder& build, PassShared& shared);

  const char* name() const override { return "shadow"; }
  void setup(FrameGraph::Builder& builder, Frame& frame) override;
  void execute(Frame& frame) override;

  // The map and this frame's views of it, for the lit passes.
  ShadowLookup lookup() const { return {&shared_.options.shadow, &map_, &views_}; }

 private:
  void rebase(const Frame& frame);  // the shown map's matrices for this frame's (camera-relative) view
  std::optional<SectionSet> litSections(const ShadowKey& key, const SectionMeshes& meshes) const;
  std::vector<VisibleSection> castersFor(const ShadowView& light, const ShadowKey& key,
                                         const std::optional<SectionSet>& lit, Frame& frame,
                                         ShadowSlices slices) const;
  void drawCasters(ShadowMap& map, const ShadowKey& key, const std::optional<SectionSet>& lit, Frame& frame,
                   ShadowSlices slices);

  struct Blocks {
    Blocks() = default;
    explicit Blocks(const LinkedProgram& p) : section(p), warp(p), shadowMatrix(p, "u_shadowMatrix") {}
    SectionUniforms section;
    WarpUniforms warp;
    gl::Uniform<glm::mat4> shadowMatrix;
  };
  struct Prop {
    Prop() = default;
    explicit Prop(const LinkedProgram& p) : prop(p, false), warp(p), shadowMatrix(p, "u_shadowMatrix") {}
    PropUniforms prop;
    WarpUniforms warp;
    gl::Uniform<glm::mat4> shadowMatrix;
  };

  struct FarTerrain {
    FarTerrain() = default;
    explicit FarTerrain(const LinkedProgram& p) : warp(p), shadowMatrix(p, "u_shadowMatrix"), tile(p) {}
    WarpUniforms warp;
    gl::Uniform<glm::mat4> shadowMatrix;
    LodTileUniforms tile;
  };

  PassShared& shared_;
  gl::ProgramWith<Blocks> opaque_, cutout_, translucent_;
  gl::ProgramWith<FarTerrain> farTerrain_;
  gl::ProgramWith<Prop> propOpaque_, propCutout_, propTranslucent_;  // each only when a placed prop needs it
  ShadowSchedule schedule_;
  ShadowPlan plan_;  // this frame's, from setup
  ShadowMap map_, building_;
  std::optional<SectionSet> buildLit_;  // a spread rebuild's lit sections, walked once at its first slice
  std::array<ShadowView, kMaxShadowCascades> views_{};
};

}  // namespace terrasol
