#include <algorithm>
#include <array>
#include <cmath>

#include "render/cave_culling.h"
#include "render/deferred_renderer.h"
#include "render/deferred_view.h"
#include "render/gl/uniforms.h"
#include "render/gl_slots.h"

// The deferred renderer's shadow pass and the shadow lookup's uniforms (lib/shadow.glsl).

namespace terrasol {

using gl::setMat4;

// The light's view, a layer per cascade: casters inside the layer's box (culled per section, and left
// out when no ray of the light reaches them or their shadow falls on nothing in view), opaque then
// alpha-tested, then translucent casters into
// their own depth and colour. With `mayReuse` (the game) the maps are kept while nothing they show
// changed, and with update_frames N > 1 a changed map is rebuilt a slice of its casters a frame into a
// second map, swapped in when complete (Luanti's spread updates: no frame pays the whole pass).
bool DeferredRenderer::shadowPass(const View& view, const SectionMeshes& meshes, bool mayReuse) {
  constexpr float kReuseCos = 0.99999962f;  // cos(0.05 degrees): 5 cm of edge movement 60 blocks away
  // The view casters are chosen for is wider than the camera's, so a map drawn over several frames, or
  // kept, still serves a camera that has turned or moved since: a new map is started once half the
  // margin is used up, and the old one is dropped at once (the whole map drawn in one frame) only once
  // all of it is (shadow_receivers.h). At sprint-flying speed a spread rebuild's 8 frames move the
  // camera about 6 blocks, which the pulled-back apex absorbs.
  constexpr float kMarginDegrees = 15.0f, kPullBack = 16.0f;
  const ShadowSettings& settings = options_.shadow;
  const int layers = shadowLayers(settings);
  shadowMap_.ensure(settings.resolution, layers);
  stats_.shadowCasters = 0;
  // Cascades are picked by distance from the camera, so only the single warped map moves ahead.
  const glm::dvec3 forward(view.forward.x, 0.0, view.forward.z);
  const double along = glm::length(forward);
  const glm::dvec3 ahead = settings.mode == ShadowMode::Warped && along > 1e-6
                               ? forward / along * static_cast<double>(settings.shiftAhead * settings.distance)
                               : glm::dvec3(0.0);
  const glm::dvec3 wantedCentre = view.camera + view.shadowCentreOffset + ahead;
  const double step = lastWantedCentre_ ? glm::length(wantedCentre - *lastWantedCentre_) : 0.0;
  lastWantedCentre_ = wantedCentre;
  const glm::dvec3 centre = mapCentre(wantedCentre);
  const std::uint64_t propsGeneration = props_ ? props_->generation() : 0;
  ShadowKey wanted{centre, view.day.toShadowLight, meshes.generation(), propsGeneration, true, std::nullopt};
  if (options_.shadowCasterCulling) wanted.receivers.emplace(view.cone.widened(kMarginDegrees, kPullBack));
  const auto serves = [&](const ViewCone& cone) {
    return !shadowKey_.receivers || shadowKey_.receivers->contains(cone);
  };
  const bool unchanged = shadowKey_.valid && shadowKey_.centre == centre &&
                         shadowKey_.meshes == wanted.meshes && shadowKey_.props == wanted.props &&
                         glm::dot(shadowKey_.toLight, wanted.toLight) > kReuseCos &&
                         serves(view.cone.widened(0.5f * kMarginDegrees, 0.5f * kPullBack));
  const int slices = mayReuse ? std::max(settings.updateFrames, 1) : 1;
  // A kept map must still cover the camera well; a jump (a teleport) redraws it whole at once.
  const double reach = kKeptShadowReach * settings.distance;
  const double used = glm::length(centre - shadowKey_.centre);
  const bool near = shadowKey_.valid && used < reach && serves(view.cone);
  if (mayReuse && unchanged && !build_) {
    rebaseShadowViews(view);
    return false;
  }
  if (slices > 1 && near) {
    if (!build_) build_ = ShadowBuild{wanted, 0, litSections(wanted, meshes)};
    building_.ensure(settings.resolution, layers);
    // The kept map serves until its centre is `reach` from the camera's. At a low frame rate a slice a
    // frame would not finish the new map by then, and the kept one would be redrawn whole in one frame,
    // again and again (hitches of a whole map). So, at the last frame's pace, a build is finished by the
    // time its own centre is half `reach` behind (the next build then has the other half) and before
    // the kept map runs out, spreading more slices a frame over the frames that leaves.
    const auto framesUntil = [&](double distance) {
      return step > 0.0 ? std::max(std::ceil(distance / step), 1.0) : 1e9;
    };
    const double frames = std::min(framesUntil(0.5 * reach - glm::length(centre - build_->key.centre)),
                                   framesUntil(reach - used));
    const int remaining = slices - build_->slice;
    const int count = std::clamp(static_cast<int>(std::ceil(remaining / frames)), 1, remaining);
    drawShadowCasters(building_, build_->key, build_->lit, view, meshes, {build_->slice, count, slices});
    build_->slice += count;
    stats_.shadowSlices = count;
    if (build_->slice == slices) {
      std::swap(shadowMap_, building_);
      shadowKey_ = build_->key;
      build_.reset();
    }
    rebaseShadowViews(view);
    return true;
  }
  build_.reset();
  shadowKey_ = wanted;
  drawShadowCasters(shadowMap_, wanted, litSections(wanted, meshes), view, meshes, {0, 1, 1});
  stats_.shadowSlices = slices;
  rebaseShadowViews(view);
  return true;
}

// The kept maps' matrices for this frame's camera (they are camera-relative).
void DeferredRenderer::rebaseShadowViews(const View& view) {
  const ShadowSettings& settings = options_.shadow;
  for (int layer = 0; layer < shadowLayers(settings); ++layer) {
    shadowViews_[static_cast<std::size_t>(layer)] = shadowViewFor(
        settings.resolution, cascadeDistance(settings, layer), shadowKey_.toLight, view.camera, shadowKey_.centre);
  }
}

// Sections no ray of the light can reach through open cells cast nothing (render/cave_culling.h). A
// spread rebuild walks once, at its first slice: sections meshed since were open cells then, so they
// are walked into like any open cell.
std::optional<SectionSet> DeferredRenderer::litSections(const ShadowKey& key,
                                                        const SectionMeshes& meshes) const {
  if (!options_.caveCulling) return std::nullopt;
  const float reach = cascadeDistance(options_.shadow, shadowLayers(options_.shadow) - 1);
  return sectionsLitFrom(meshes, key.toLight, key.centre, static_cast<int>(std::ceil(reach / 16.0f)) + 2);
}

// Slices `slices.first` .. `first + count - 1` of `slices.of` of the casters (by a hash of their
// position, so each is in exactly one) into `map`, cleared first by slice 0.
void DeferredRenderer::drawShadowCasters(ShadowMap& map, const ShadowKey& key,
                                         const std::optional<SectionSet>& lit, const View& view,
                                         const SectionMeshes& meshes, ShadowSlices slices) {
  const ShadowSettings& settings = options_.shadow;
  const int layers = shadowLayers(settings);
  glViewport(0, 0, settings.resolution, settings.resolution);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);   // single faces (the mesher drops hidden ones) must cast from both sides
  glEnable(GL_DEPTH_CLAMP);  // casters above the near plane still cast, flattened onto it
  glDisable(GL_BLEND);
  const auto inSlice = [&](SectionPos p) {
    const auto h = static_cast<std::uint32_t>(p.x * 73856093) ^ static_cast<std::uint32_t>(p.section * 19349663) ^
                   static_cast<std::uint32_t>(p.z * 83492791);
    const int slice = static_cast<int>(h % static_cast<std::uint32_t>(slices.of));
    return slice >= slices.first && slice < slices.first + slices.count;
  };
  const float farDepth = 1.0f;
  const glm::vec3 fromLight = -key.toLight;
  for (int layer = 0; layer < layers; ++layer) {
    const ShadowView light =
        shadowViewFor(settings.resolution, cascadeDistance(settings, layer), key.toLight, view.camera, key.centre);
    std::vector<Visible> casters = sectionsInside(frustumPlanes(light.matrix), view.camera, meshes);
    if (lit) {
      const auto dark = std::remove_if(casters.begin(), casters.end(),
                                       [&](const Visible& v) { return !lit->contains(v.pos); });
      stats_.shadowCastersHidden += static_cast<int>(casters.end() - dark);
      casters.erase(dark, casters.end());
    }
    if (key.receivers) {
      const auto unseen = std::remove_if(casters.begin(), casters.end(), [&](const Visible& v) {
        const glm::dvec3 lo = view.camera + glm::dvec3(v.offset);
        return !key.receivers->mayShade(lo, lo + 16.0, key.toLight);
      });
      stats_.shadowCastersOffView += static_cast<int>(casters.end() - unseen);
      casters.erase(unseen, casters.end());
    }
    if (slices.count < slices.of) {
      casters.erase(std::remove_if(casters.begin(), casters.end(), [&](const Visible& v) { return !inSlice(v.pos); }),
                    casters.end());
    }
    stats_.shadowCasters += static_cast<int>(casters.size());
    const GLuint opaque = map.framebuffer(layer), translucent = map.translucentFramebuffer(layer);
    if (slices.first == 0) {
      const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
      glClearNamedFramebufferfv(opaque, GL_DEPTH, 0, &farDepth);
      glClearNamedFramebufferfv(translucent, GL_COLOR, 0, clear);
      glClearNamedFramebufferfv(translucent, GL_DEPTH, 0, &farDepth);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, opaque);
    for (const GLuint program : {shadow_.id(), shadowCutout_.id(), shadowTranslucent_.id()}) {
      setMat4(program, "u_shadowMatrix", light.matrix);
      setWarpUniforms(program);
    }
    // Nearest the light first: the depth test then rejects what lies behind before it is shaded.
    const SectionDraw how{DrawOrder::NearestFirst, fromLight, false, false, SectionMeshes::View::Light};
    drawSections(shadow_.id(), casters, meshes, MeshLayer::Opaque, how);
    drawSections(shadowCutout_.id(), casters, meshes, MeshLayer::Cutout, how);
    // Props cast in the first slice of a spread rebuild (they are few).
    std::vector<int> propCasters;
    if (props_ && propShadow_.id() && slices.first == 0) {
      propCasters = propsInside(frustumPlanes(light.matrix), view.camera, *props_);
      stats_.propShadowCasters += static_cast<int>(propCasters.size());
      for (const GLuint program : {propShadow_.id(), propShadowCutout_.id(), propShadowTranslucent_.id()}) {
        if (!program) continue;
        setMat4(program, "u_shadowMatrix", light.matrix);
        setWarpUniforms(program);
      }
      drawProps(propShadow_.id(), *props_, propCasters, view.camera, AlphaMode::Opaque, false);
      if (propShadowCutout_.id()) drawProps(propShadowCutout_.id(), *props_, propCasters, view.camera, AlphaMode::Mask, false);
    }
    // Translucent casters into their own depth and colour: the nearest one filters the light.
    glBindFramebuffer(GL_FRAMEBUFFER, translucent);
    drawSections(shadowTranslucent_.id(), casters, meshes, MeshLayer::Translucent, how);
    if (propShadowTranslucent_.id() && !propCasters.empty()) {
      drawProps(propShadowTranslucent_.id(), *props_, propCasters, view.camera, AlphaMode::Blend, false);
    }
  }
  glDisable(GL_DEPTH_CLAMP);
}

// The maps' centre stays put until the camera has moved kRecentreTexels (of the finest layer) from it.
// Snapping to whole texels alone keeps an unwarped map stable in exact arithmetic, but the warp around a
// centre that steps moves world points by fractions of a texel, and even unwarped casters' float
// vertices round differently after a step, so every step flips a few shadow edges. Re-centring rarely
// turns that crawl into an occasional step. (Cascades are picked with a 10 % margin, far more.)
glm::dvec3 DeferredRenderer::mapCentre(glm::dvec3 wanted) {
  constexpr double kRecentreTexels = 8.0;
  const ShadowSettings& settings = options_.shadow;
  const double texel = 2.0 * cascadeDistance(settings, 0) / std::max(settings.resolution, 1);
  if (!warpCentre_ || glm::length(wanted - *warpCentre_) > kRecentreTexels * texel) warpCentre_ = wanted;
  return *warpCentre_;
}

// Cascades are never warped.
void DeferredRenderer::setWarpUniforms(GLuint program) const {
  const bool warped = options_.shadow.mode == ShadowMode::Warped;
  glProgramUniform1i(program, glGetUniformLocation(program, "u_shadowWarp"),
                     warped ? static_cast<int>(options_.shadow.warp) : static_cast<int>(ShadowWarp::None));
  glProgramUniform1f(program, glGetUniformLocation(program, "u_shadowWarpStrength"),
                     std::clamp(options_.shadow.warpStrength, 0.0f, 0.999f));
}

void DeferredRenderer::setShadowUniforms(GLuint program, bool live) const {
  const ShadowSettings& settings = options_.shadow;
  setWarpUniforms(program);
  const int layers = shadowLayers(settings);
  std::array<glm::mat4, kMaxShadowCascades> matrices{};
  std::array<float, kMaxShadowCascades> texels{}, ranges{};
  for (int i = 0; i < layers; ++i) {
    const ShadowView& v = shadowViews_[static_cast<std::size_t>(i)];
    matrices[static_cast<std::size_t>(i)] = v.matrix;
    texels[static_cast<std::size_t>(i)] = v.texelWorld;
    ranges[static_cast<std::size_t>(i)] = v.depthRange;
  }
  glProgramUniform1i(program, glGetUniformLocation(program, "u_cascades"), layers);
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "u_shadowMatrices"), layers, GL_FALSE,
                            glm::value_ptr(matrices[0]));
  glProgramUniform1fv(program, glGetUniformLocation(program, "u_shadowTexelWorlds"), layers, texels.data());
  glProgramUniform1fv(program, glGetUniformLocation(program, "u_shadowDepthRanges"), layers, ranges.data());
  glProgramUniform1f(program, glGetUniformLocation(program, "u_shadowResolution"), static_cast<float>(settings.resolution));
  glProgramUniform1f(program, glGetUniformLocation(program, "u_pcfRadius"), std::max(settings.pcfRadius, 0.0f));
  glProgramUniform1i(program, glGetUniformLocation(program, "u_pcfRadiusInBlocks"), settings.pcfRadiusInBlocks ? 1 : 0);
  glProgramUniform1i(program, glGetUniformLocation(program, "u_shadowLive"), live ? 1 : 0);
  glBindTextureUnit(slots::kUnitShadowMap, shadowMap_.depth());
  glBindTextureUnit(slots::kUnitTransmittance, shadowMap_.transmittance());
}

}  // namespace terrasol
