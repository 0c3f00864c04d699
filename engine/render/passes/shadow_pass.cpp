#include "render/passes/shadow_pass.h"

#include <algorithm>
#include <cmath>

#include "render/lod_draw.h"

namespace terrasol {

ShadowPass::ShadowPass(const VariantBuilder& build, PassShared& shared)
    : shared_(shared), schedule_(shared.options.shadow, shared.options.shadowCasterCulling) {
  if (!shared.options.shadow.enabled) return;
  using BlocksProgram = gl::ProgramWith<Blocks>;
  using PropProgram = gl::ProgramWith<Prop>;
  opaque_ = BlocksProgram(build("shadow.vert", "shadow.frag"));
  cutout_ = BlocksProgram(build("shadow.vert", "shadow.frag", {{"CUTOUT", "1"}}));
  translucent_ = BlocksProgram(build("shadow.vert", "shadow.frag", {{"TRANSLUCENT", "1"}}));
  farTerrain_ = gl::ProgramWith<FarTerrain>(build("lod.vert", "lod_shadow.frag", {{"SHADOW", "1"}}));
  const PropNeeds& needs = shared.options.props;
  if (!needs.any) return;
  propOpaque_ = PropProgram(build("prop_shadow.vert", "prop_shadow.frag"));
  if (needs.mask) propCutout_ = PropProgram(build("prop_shadow.vert", "prop_shadow.frag", {{"CUTOUT", "1"}}));
  if (needs.blend) {
    propTranslucent_ = PropProgram(build("prop_shadow.vert", "prop_shadow.frag", {{"TRANSLUCENT", "1"}}));
  }
}

void ShadowPass::setup(FrameGraph::Builder& builder, Frame& frame) {
  if (!shared_.options.shadow.enabled) return builder.skip("shadows are off");
  if (!frame.view.lightUp) return builder.skip("neither sun nor moon is above the horizon");
  ShadowFrame schedule;
  schedule.camera = frame.view.camera;
  schedule.centreOffset = frame.view.shadowCentreOffset;
  schedule.forward = frame.view.forward;
  schedule.toLight = frame.view.day.toShadowLight;
  schedule.meshes = frame.meshes.generation();
  schedule.props = frame.props ? frame.props->generation() : 0;
  const bool farCasts = frame.inputs.lod && frame.inputs.lodShadows;
  schedule.far = farCasts ? frame.inputs.lod->generation() : 0;
  schedule.cone = frame.view.cone;
  schedule.mayReuse = frame.inputs.reuseShadowMap;
  plan_ = schedule_.plan(schedule);
  if (plan_.action == ShadowPlan::Action::Keep) {
    schedule_.commit(plan_);
    rebase(frame);
    frame.shadowDrawn = true;
    return builder.skip("kept: nothing it shows changed and it still serves the view");
  }
  builder.write(frame.resources.shadowMap);
}

void ShadowPass::execute(Frame& frame) {
  const ShadowSettings& settings = shared_.options.shadow;
  const int layers = shadowLayers(settings);
  map_.ensure(settings.resolution, layers);
  schedule_.commit(plan_);
  if (plan_.action == ShadowPlan::Action::Spread) {
    if (plan_.startsBuild) buildLit_ = litSections(plan_.key, frame.meshes);
    building_.ensure(settings.resolution, layers);
    drawCasters(building_, plan_.key, buildLit_, frame, plan_.slices);
    if (plan_.completes) std::swap(map_, building_);
  } else {
    drawCasters(map_, plan_.key, litSections(plan_.key, frame.meshes), frame, plan_.slices);
  }
  frame.stats.shadowSlices = plan_.slicesDrawn;
  rebase(frame);
  frame.shadowDrawn = true;
}

void ShadowPass::rebase(const Frame& frame) {
  const ShadowSettings& settings = shared_.options.shadow;
  const ShadowKey& shown = schedule_.shown();
  for (int layer = 0; layer < shadowLayers(settings); ++layer) {
    views_[static_cast<std::size_t>(layer)] =
        shadowViewFor(settings.resolution, cascadeDistance(settings, layer), shown.toLight, frame.view.camera,
                      shown.centre);
  }
}

// Sections no ray of the light can reach through open cells cast nothing (render/cave_culling.h). A
// spread rebuild walks once, at its first slice: sections meshed since were open cells then, so they
// are walked into like any open cell.
std::optional<SectionSet> ShadowPass::litSections(const ShadowKey& key, const SectionMeshes& meshes) const {
  if (!shared_.options.caveCulling) return std::nullopt;
  const ShadowSettings& settings = shared_.options.shadow;
  const float reach = cascadeDistance(settings, shadowLayers(settings) - 1);
  return sectionsLitFrom(meshes, key.toLight, key.centre, static_cast<int>(std::ceil(reach / 16.0f)) + 2);
}

// The sections inside `light`'s box that cast into this draw: lit by it (`lit`), shading something in
// view (the key's receivers), and in this draw's slices (by a hash of their position, so each is in
// exactly one). Counts what is left out.
std::vector<VisibleSection> ShadowPass::castersFor(const ShadowView& light, const ShadowKey& key,
                                                   const std::optional<SectionSet>& lit, Frame& frame,
                                                   ShadowSlices slices) const {
  const glm::dvec3 camera = frame.view.camera;
  FrameStats& stats = frame.stats;
  const auto inSlice = [&](SectionPos p) {
    const auto h = static_cast<std::uint32_t>(p.x * 73856093) ^
                   static_cast<std::uint32_t>(p.section * 19349663) ^
                   static_cast<std::uint32_t>(p.z * 83492791);
    const int slice = static_cast<int>(h % static_cast<std::uint32_t>(slices.of));
    return slice >= slices.first && slice < slices.first + slices.count;
  };
  std::vector<VisibleSection> casters = sectionsInside(frustumPlanes(light.matrix), camera, frame.meshes);
  const auto drop = [&](auto&& out) {
    const auto end = std::remove_if(casters.begin(), casters.end(), out);
    const int dropped = static_cast<int>(casters.end() - end);
    casters.erase(end, casters.end());
    return dropped;
  };
  if (lit) stats.shadowCastersHidden += drop([&](const VisibleSection& v) { return !lit->contains(v.pos); });
  if (key.receivers) {
    stats.shadowCastersOffView += drop([&](const VisibleSection& v) {
      const glm::dvec3 lo = camera + glm::dvec3(v.offset);
      return !key.receivers->mayShade(lo, lo + 16.0, key.toLight);
    });
  }
  if (slices.count < slices.of) drop([&](const VisibleSection& v) { return !inSlice(v.pos); });
  stats.shadowCasters += static_cast<int>(casters.size());
  return casters;
}

// Slices `slices.first` .. `first + count - 1` of `slices.of` of the casters (by a hash of their
// position, so each is in exactly one) into `map`, cleared first by slice 0.
void ShadowPass::drawCasters(ShadowMap& map, const ShadowKey& key, const std::optional<SectionSet>& lit,
                             Frame& frame, ShadowSlices slices) {
  const ShadowSettings& settings = shared_.options.shadow;
  FrameStats& stats = frame.stats;
  const glm::dvec3 camera = frame.view.camera;
  glViewport(0, 0, settings.resolution, settings.resolution);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);   // single faces (the mesher drops hidden ones) must cast from both sides
  glEnable(GL_DEPTH_CLAMP);  // casters above the near plane still cast, flattened onto it
  glDisable(GL_BLEND);
  const float farDepth = 1.0f;
  const glm::vec3 fromLight = -key.toLight;
  for (int layer = 0; layer < shadowLayers(settings); ++layer) {
    const ShadowView light =
        shadowViewFor(settings.resolution, cascadeDistance(settings, layer), key.toLight, camera, key.centre);
    const std::vector<VisibleSection> casters = castersFor(light, key, lit, frame, slices);
    const GLuint opaque = map.framebuffer(layer), translucent = map.translucentFramebuffer(layer);
    if (slices.first == 0) {
      const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
      glClearNamedFramebufferfv(opaque, GL_DEPTH, 0, &farDepth);
      glClearNamedFramebufferfv(translucent, GL_COLOR, 0, clear);
      glClearNamedFramebufferfv(translucent, GL_DEPTH, 0, &farDepth);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, opaque);
    for (const Blocks* u : {&opaque_.u, &cutout_.u, &translucent_.u}) {
      u->shadowMatrix.set(light.matrix);
      u->warp.set(settings);
    }
    // Nearest the light first: the depth test then rejects what lies behind before it is shaded.
    const SectionDraw how{DrawOrder::NearestFirst, fromLight, false, nullptr, SectionMeshes::View::Light};
    const BlockTextures& textures = shared_.textures;
    drawSections(opaque_.id(), opaque_.u.section, textures, casters, frame.meshes, MeshLayer::Opaque, how);
    drawSections(cutout_.id(), cutout_.u.section, textures, casters, frame.meshes, MeshLayer::Cutout, how);
    // Props cast in the first slice of a spread rebuild (they are few).
    std::vector<int> propCasters;
    if (frame.props && propOpaque_ && slices.first == 0) {
      propCasters = propsInside(frustumPlanes(light.matrix), camera, *frame.props);
      stats.propShadowCasters += static_cast<int>(propCasters.size());
      for (const Prop* u : {&propOpaque_.u, &propCutout_.u, &propTranslucent_.u}) {
        u->shadowMatrix.set(light.matrix);  // nothing where the variant was not built
        u->warp.set(settings);
      }
      const Props& props = *frame.props;
      drawProps(propOpaque_.id(), propOpaque_.u.prop, props, propCasters, camera, AlphaMode::Opaque, false);
      if (propCutout_) {
        drawProps(propCutout_.id(), propCutout_.u.prop, props, propCasters, camera, AlphaMode::Mask, false);
      }
    }
    // Far terrain casts in the first slice too: out where the map reaches past full detail, and from
    // ridges beyond it (depth clamp keeps those above the near plane).
    if (frame.inputs.lod && frame.inputs.lodShadows && !frame.inputs.lod->empty() && slices.first == 0) {
      glUseProgram(farTerrain_.id());
      farTerrain_.u.shadowMatrix.set(light.matrix);
      farTerrain_.u.warp.set(settings);
      stats.lodShadowCasters +=
          drawLodTiles(*frame.inputs.lod, frustumPlanes(light.matrix), camera, farTerrain_.u.tile, false)
              .drawn;
    }
    // Translucent casters into their own depth and colour: the nearest one filters the light.
    glBindFramebuffer(GL_FRAMEBUFFER, translucent);
    drawSections(translucent_.id(), translucent_.u.section, textures, casters, frame.meshes,
                 MeshLayer::Translucent, how);
    if (propTranslucent_ && !propCasters.empty()) {
      drawProps(propTranslucent_.id(), propTranslucent_.u.prop, *frame.props, propCasters, camera,
                AlphaMode::Blend, false);
    }
  }
  glDisable(GL_DEPTH_CLAMP);
}

}  // namespace terrasol
