#include "render/deferred_renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "core/camera.h"
#include "core/lightmap.h"
#include "render/cave_culling.h"
#include "render/deferred_view.h"
#include "render/gl/program.h"
#include "render/gl/uniforms.h"
#include "render/gl_slots.h"
#include "render/shader_defines.h"

namespace terrasol {

using gl::setMat4;
using gl::setVec3;

namespace {

// Scales the scene's radiance (noon sun ~3, full sky light 1) into the tone curve's range, so a
// sunlit surface shows about its texture colour, as in vanilla.
constexpr float kExposure = 0.3f;

// Builds a program and names its variant in `names`: the fragment stage and the defines that chose it.
gl::Program build(const ShaderPreprocessor& shaders, std::vector<std::string>& names, const char* vertex,
                  const char* fragment, std::vector<ShaderDefine> extra = {}) {
  std::string name = std::string(fragment).substr(0, std::string(fragment).find('.'));
  for (const ShaderDefine& d : extra) {
    name += "+";
    name += d.name;
    if (d.value != "1") name += "=" + d.value;
  }
  names.push_back(name);
  std::vector<ShaderDefine> defines = rendererDefines();
  for (auto& d : extra) defines.push_back(std::move(d));
  return buildProgram(shaders, {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, defines);
}

std::vector<ShaderDefine> with(std::vector<ShaderDefine> a, const std::vector<ShaderDefine>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<ShaderDefine> lightingDefines(const RendererOptions& options) {
  std::vector<ShaderDefine> defines;
  if (options.ggxSpecular) defines.push_back({"SPECULAR_GGX", "1"});
  if (options.shadow.enabled) {
    // The filter is fixed per renderer, so each shader holds only its own taps: a software rasterizer
    // runs every branch that any pixel of a block takes, and a loop over a uniform count costs more.
    // Neither define: one tap.
    defines.push_back({"SHADOWS", "1"});
    if (const int n = std::clamp(options.shadow.pcfSamples, 0, 8); n > 0) {
      if (options.shadow.pcfPattern == PcfPattern::Disk) {
        defines.push_back({"PCF_DISK", "1"});
      } else if (options.shadow.pcfPattern == PcfPattern::Tent) {
        defines.push_back({"PCF_TENT", "1"});
      } else {
        defines.push_back({"PCF_GRID_SIDE", std::to_string(2 * n + 1)});
      }
    }
  }
  return defines;
}

// The maps no loaded pack has: nothing to sample (block_surface.glsl) and nothing to keep for them.
// Props always carry a material (metallic-roughness becomes a LabPBR _s texel), and may have normal maps.
GBufferContents contentsFor(const Atlas& atlas, const RendererOptions& options) {
  return {!options.leaveOutAbsentMaps || atlas.anyNormalMap || options.props.normalMaps,
          !options.leaveOutAbsentMaps || atlas.anySpecularMap || options.props.any};
}

// Sky light's colour: the zenith's hue at a fixed brightness (the lightmap carries the brightness).
glm::vec3 ambientTint(glm::vec3 zenith) {
  const float luminance = glm::dot(zenith, glm::vec3(0.2126f, 0.7152f, 0.0722f));
  const glm::vec3 hue = luminance > 1e-5f ? zenith / luminance : glm::vec3(1.0f);
  return glm::mix(glm::vec3(1.0f), glm::clamp(hue, 0.0f, 4.0f), 0.4f);
}

}  // namespace

DeferredRenderer::DeferredRenderer(const ShaderPreprocessor& shaders, const Atlas& atlas,
                                   const BiomeTints& tints, const RendererOptions& options)
    : contents_(contentsFor(atlas, options)),
      geometry_(build(shaders, variants_, "gbuffer.vert", "gbuffer.frag", contents_.defines())),
      cutout_(build(shaders, variants_, "gbuffer.vert", "gbuffer.frag",
                    with({{"CUTOUT", "1"}}, contents_.defines()))),
      lighting_(build(shaders, variants_, "fullscreen.vert", "lighting.frag",
                      with(lightingDefines(options), contents_.defines()))),
      sky_(build(shaders, variants_, "fullscreen.vert", "sky.frag")),
      translucent_(build(shaders, variants_, "gbuffer.vert", "translucent.frag",
                         with(lightingDefines(options), contents_.defines()))),
      shadow_(options.shadow.enabled ? build(shaders, variants_, "shadow.vert", "shadow.frag")
                                     : gl::Program()),
      shadowCutout_(options.shadow.enabled
                        ? build(shaders, variants_, "shadow.vert", "shadow.frag", {{"CUTOUT", "1"}})
                        : gl::Program()),
      shadowTranslucent_(options.shadow.enabled
                             ? build(shaders, variants_, "shadow.vert", "shadow.frag", {{"TRANSLUCENT", "1"}})
                             : gl::Program()),
      final_(build(shaders, variants_, "fullscreen.vert", "final.frag")),
      debug_(build(shaders, variants_, "fullscreen.vert", "debug_view.frag", contents_.defines())),
      outline_(build(shaders, variants_, "outline.vert", "outline.frag")),
      textures_(atlas, tints),
      empty_(gl::VertexArray::create()),
      options_(options),
      gpuTimer_(!softwareRenderer()) {
  if (options.props.any) buildPropPrograms(shaders);
}

// Only the variants the placed props need: MASK and BLEND materials, shadows.
void DeferredRenderer::buildPropPrograms(const ShaderPreprocessor& shaders) {
  const PropNeeds& needs = options_.props;
  propGeometry_ = build(shaders, variants_, "prop.vert", "prop.frag", contents_.defines());
  if (needs.mask) {
    propCutout_ = build(shaders, variants_, "prop.vert", "prop.frag", with({{"CUTOUT", "1"}}, contents_.defines()));
  }
  if (needs.blend) {
    propTranslucent_ = build(shaders, variants_, "prop.vert", "prop_translucent.frag",
                             with(lightingDefines(options_), contents_.defines()));
  }
  if (!options_.shadow.enabled) return;
  propShadow_ = build(shaders, variants_, "prop_shadow.vert", "prop_shadow.frag");
  if (needs.mask) propShadowCutout_ = build(shaders, variants_, "prop_shadow.vert", "prop_shadow.frag", {{"CUTOUT", "1"}});
  if (needs.blend) {
    propShadowTranslucent_ = build(shaders, variants_, "prop_shadow.vert", "prop_shadow.frag", {{"TRANSLUCENT", "1"}});
  }
}

void DeferredRenderer::render(const FrameInputs& frame, const SectionMeshes& meshes, GLuint framebuffer,
                              glm::ivec2 size, std::vector<PassTiming>* timings) {
  if (size.x <= 0 || size.y <= 0) return;  // a minimised window: nothing to draw
  if (!gbuffer_ || gbuffer_->size() != size) gbuffer_.emplace(size, contents_);

  View view;
  view.camera = frame.cameraPosition;
  Camera camera;  // at the origin: everything is drawn relative to the camera
  const glm::dvec3 forward = frame.cameraLookAt - frame.cameraPosition;
  camera.lookAt = glm::vec3(forward);
  camera.up = glm::vec3(frame.cameraUp);
  camera.fovDegrees = frame.fovDegrees;
  camera.farPlane = std::max(2.0f * frame.viewDistance, 256.0f);
  const glm::mat4 projection = camera.projection(static_cast<float>(size.x) / static_cast<float>(size.y));
  view.viewProjection = projection * camera.view();
  view.inverseViewProjection = glm::inverse(view.viewProjection);
  view.frustum = frustumPlanes(view.viewProjection);
  view.nearFar = {camera.nearPlane, camera.farPlane};
  view.fogRange = {0.8f * frame.viewDistance, frame.viewDistance};
  view.day = dayStateAt(frame.ticks, frame.sunPathRotation);
  view.materialAo = frame.materialAo;
  view.shadowCentreOffset = frame.shadowCentreOffset;
  const double forwardLength = glm::length(forward);
  if (forwardLength > 1e-9) view.forward = forward / forwardLength;

  view.lightmap = lightmapColours(view.day, frame.ticks);
  textures_.update(frame.ticks);

  PassClock clock(timings, gpuTimer_);
  props_ = frame.props && !frame.props->empty() && options_.props.any ? frame.props : nullptr;
  cull(view, meshes);
  // Receivers down to the world's bottom: the lowest visible section jumps by a hundred blocks as a
  // cave comes into view, and a floor that followed it would have the map redrawn at every jump.
  view.cone.eye = view.camera;
  view.cone.forward = glm::vec3(view.forward);  // unit, or -z for a degenerate look-at
  view.cone.up = camera.up;
  view.cone.fovDegrees = camera.fovDegrees;
  view.cone.aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
  view.cone.farPlane = camera.farPlane;
  view.cone.floorY = kMinY;
  // Below 0.1 % of its strength the light can show nothing (it is 0 at and under the horizon).
  view.shadowLive = options_.shadow.enabled && view.day.directStrength > 1e-3f;
  if (view.shadowLive) {
    if (shadowPass(view, meshes, frame.reuseShadowMap)) {
      clock.lap("shadow");
    } else {
      stats_.passesSkipped.push_back({"shadow", "kept: the light, the map's centre and the meshes did not change"});
    }
  } else {
    stats_.passesSkipped.push_back({"shadow", options_.shadow.enabled ? "neither sun nor moon is above the horizon"
                                                                      : "shadows are off"});
  }
  geometryPass(view, meshes);
  clock.lap("geometry");
  lastGeometry_ = {view.camera, view.viewProjection, view.inverseViewProjection, view.day.toShadowLight, view.shadowLive,
               view.shadowLive ? shadowViews_[0].texelWorld : 0.0f};
  if (frame.debugView != DebugView::None) {
    glProgramUniform1i(debug_.id(), glGetUniformLocation(debug_.id(), "u_view"), static_cast<int>(frame.debugView));
    debugPass(view, framebuffer, size);
    clock.lap("debug_view");
    for (const char* pass : {"lighting", "translucent", "final"}) {
      stats_.passesSkipped.push_back({pass, "a debug view shows the G-buffer instead"});
    }
  } else {
    lightingPass(view);
    clock.lap("lighting");
    if (visibleQuads(MeshLayer::Translucent) > 0 || visibleBlendedProps()) {
      translucentPass(view, meshes);
      clock.lap("translucent");
    } else {
      stats_.passesSkipped.push_back({"translucent", "no translucent geometry in view"});
    }
    finalPass(framebuffer, size);
    clock.lap("final");
  }
  if (frame.outline) {
    outlinePass(view, *frame.outline, framebuffer, size);
    clock.lap("outline");
  }
}

void DeferredRenderer::geometryPass(const View& view, const SectionMeshes& meshes) {
  const GLuint fbo = gbuffer_->geometryFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, gbuffer_->size().x, gbuffer_->size().y);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float farDepth = 1.0f;
  for (int i = 0; i < gbuffer::kTargets; ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
  glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  for (const GLuint program : {geometry_.id(), cutout_.id()}) {
    setMat4(program, "u_viewProjection", view.viewProjection);
    glProgramUniform2f(program, glGetUniformLocation(program, "u_viewportPixels"),
                       static_cast<float>(gbuffer_->size().x), static_cast<float>(gbuffer_->size().y));
    glProgramUniform1i(program, glGetUniformLocation(program, "u_sealMergedEdges"), 1);
  }
  const SectionDraw how{DrawOrder::NearestFirst, glm::vec3(0.0f), options_.cullFacesAway, true};
  drawSections(geometry_.id(), visible_, meshes, MeshLayer::Opaque, how);
  drawSections(cutout_.id(), visible_, meshes, MeshLayer::Cutout, how);
  if (props_) {
    setMat4(propGeometry_.id(), "u_viewProjection", view.viewProjection);
    drawProps(propGeometry_.id(), *props_, visibleProps_, view.camera, AlphaMode::Opaque, true);
    if (propCutout_.id()) {
      setMat4(propCutout_.id(), "u_viewProjection", view.viewProjection);
      drawProps(propCutout_.id(), *props_, visibleProps_, view.camera, AlphaMode::Mask, true);
    }
  }
}

std::vector<DeferredRenderer::Visible> DeferredRenderer::sectionsInside(const FrustumPlanes& planes, glm::dvec3 camera,
                                                                        const SectionMeshes& meshes, int* outside) {
  std::vector<Visible> inside;
  for (const auto& [pos, section] : meshes.sections()) {
    // In double: far from the origin a float cannot hold both the section and the small offset.
    const glm::dvec3 corner(pos.x * 16.0, kMinY + pos.section * 16.0, pos.z * 16.0);
    const glm::vec3 offset(corner - camera);
    if (boxVisible(planes, offset, 16.0f)) {
      inside.push_back({&section, offset, pos});
    } else if (outside) {
      ++*outside;
    }
  }
  return inside;
}

void DeferredRenderer::cull(const View& view, const SectionMeshes& meshes) {
  stats_ = {};
  visible_ = sectionsInside(view.frustum, view.camera, meshes, &stats_.sectionsCulled);
  if (options_.caveCulling) {
    const int radius = static_cast<int>(std::ceil(view.fogRange.y / 16.0f)) + 2;
    const SectionSet reached = reachableSections(meshes, view.camera, view.frustum, radius);
    const auto hidden = std::remove_if(visible_.begin(), visible_.end(), [&](const Visible& v) { return !reached.contains(v.pos); });
    stats_.sectionsHidden = static_cast<int>(visible_.end() - hidden);
    visible_.erase(hidden, visible_.end());
  }
  stats_.sectionsDrawn = static_cast<int>(visible_.size());
  visibleProps_.clear();
  if (props_) {
    visibleProps_ = propsInside(view.frustum, view.camera, *props_);
    stats_.propsDrawn = static_cast<int>(visibleProps_.size());
    stats_.propsCulled = static_cast<int>(props_->instances().size() - visibleProps_.size());
  }
}

std::size_t DeferredRenderer::visibleQuads(MeshLayer layer) const {
  std::size_t quads = 0;
  for (const Visible& v : visible_) quads += static_cast<std::size_t>(v.section->layers[static_cast<std::size_t>(layer)].quads);
  return quads;
}

void DeferredRenderer::drawSections(GLuint program, const std::vector<Visible>& sections, const SectionMeshes& meshes,
                                    MeshLayer layer, const SectionDraw& how) {
  struct Draw {
    const SectionMeshes::Layer* layer;
    glm::vec3 offset;
    float key;
  };
  const bool alongAxis = glm::dot(how.axis, how.axis) > 0.0f;
  std::vector<Draw> draws;
  for (const Visible& v : sections) {
    const auto& l = v.section->layers[static_cast<std::size_t>(layer)];
    const glm::vec3 centre = v.offset + glm::vec3(8.0f);
    if (l.quads > 0) draws.push_back({&l, v.offset, alongAxis ? glm::dot(centre, how.axis) : glm::length(centre)});
  }
  if (draws.empty()) return;
  std::stable_sort(draws.begin(), draws.end(), [&](const Draw& a, const Draw& b) {
    return how.order == DrawOrder::NearestFirst ? a.key < b.key : a.key > b.key;
  });

  glUseProgram(program);
  textures_.bind(program);
  const GLint offsetLocation = glGetUniformLocation(program, "u_sectionOffset");
  glBindVertexArray(meshes.vertexArray());
  for (const Draw& d : draws) {
    meshes.bindLayer(*d.layer);
    glProgramUniform3fv(program, offsetLocation, 1, glm::value_ptr(d.offset));
    // Face groups turned away from the camera for the whole section are never drawn: a face of normal
    // +x lies in a plane at x >= the section's corner, so it faces away from a camera (at 0) whenever
    // the corner's x >= 0; likewise for every direction. Runs of drawn groups become one range each.
    const glm::vec3 lo = d.offset, hi = d.offset + glm::vec3(16.0f);
    const bool away[SectionMeshes::kFaceGroups] = {hi.x <= 0.0f, lo.x >= 0.0f, hi.y <= 0.0f, lo.y >= 0.0f,
                                                   hi.z <= 0.0f, lo.z >= 0.0f, false};
    GLsizei counts[SectionMeshes::kFaceGroups];
    const void* offsets[SectionMeshes::kFaceGroups];
    GLsizei ranges = 0;
    for (int g = 0; g < SectionMeshes::kFaceGroups; ++g) {
      const auto [first, end] = d.layer->range(g, how.view);
      const GLsizei quads = end - first;
      if (quads == 0) continue;
      if (how.cullFacesAway && away[g]) {
        if (how.countQuads) stats_.quadsFacingAway += quads;
        continue;
      }
      const auto offset =
          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 6 * sizeof(GLuint));
      if (ranges > 0 && static_cast<const char*>(offsets[ranges - 1]) + counts[ranges - 1] * sizeof(GLuint) == offset) {
        counts[ranges - 1] += quads * 6;
      } else {
        counts[ranges] = quads * 6;
        offsets[ranges++] = offset;
      }
    }
    if (how.countQuads) {
      for (GLsizei r = 0; r < ranges; ++r) stats_.quadsDrawn += counts[r] / 6;
    }
    if (ranges > 0) glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, offsets, ranges);
  }
  glBindVertexArray(0);
}

void DeferredRenderer::setLightingUniforms(GLuint program, const View& view) const {
  const DayState& day = view.day;
  setVec3(program, "u_toLight", day.toShadowLight);
  setVec3(program, "u_lightColor", day.lightColor);
  setVec3(program, "u_ambientTint", ambientTint(day.skyZenith));
  glProgramUniform1i(program, glGetUniformLocation(program, "u_materialAo"), view.materialAo ? 1 : 0);
  setVec3(program, "u_lightmapSky", view.lightmap.sky);
  setVec3(program, "u_lightmapBlock", view.lightmap.block);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_lightmapFloor"), view.lightmap.floor);
  if (options_.shadow.enabled) setShadowUniforms(program, view.shadowLive);
}

// The sky and the fog that fades distant surfaces into it (lighting and translucent passes).
void DeferredRenderer::setSkyUniforms(GLuint program, const View& view) const {
  const DayState& day = view.day;
  setVec3(program, "u_skyZenith", day.skyZenith);
  setVec3(program, "u_skyHorizon", day.skyHorizon);
  setVec3(program, "u_toSun", day.toSun);
  setVec3(program, "u_toMoon", day.toMoon);
  setVec3(program, "u_sunColor", day.sunColor);
  setVec3(program, "u_moonColor", day.moonColor);
  glProgramUniform1f(program, glGetUniformLocation(program, "u_starVisibility"), day.starVisibility);
  glProgramUniform2fv(program, glGetUniformLocation(program, "u_fogRange"), 1, glm::value_ptr(view.fogRange));
}

// Lighting where the geometry pass drew something, sky elsewhere. Both draw a full-screen triangle at
// depth 1 against a copy of the scene's depth, so a CPU rasterizer's early depth test skips the other
// pass's pixels, block by block, before shading them.
void DeferredRenderer::lightingPass(const View& view) {
  const GLuint program = lighting_.id();
  setLightingUniforms(program, view);
  setSkyUniforms(program, view);
  setMat4(program, "u_inverseViewProjection", view.inverseViewProjection);
  setSkyUniforms(sky_.id(), view);
  setMat4(sky_.id(), "u_inverseViewProjection", view.inverseViewProjection);

  gbuffer_->copyDepthForLighting();
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_->lightingFramebuffer());
  glViewport(0, 0, gbuffer_->size().x, gbuffer_->size().y);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  gbuffer_->bindForReading();
  glBindVertexArray(empty_.id());
  glUseProgram(program);
  glDepthFunc(GL_GREATER);  // depth 1 lies beyond what was drawn
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(sky_.id());
  glDepthFunc(GL_LEQUAL);  // only the cleared depth, 1, is not nearer
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

void DeferredRenderer::translucentPass(const View& view, const SectionMeshes& meshes) {
  setLightingUniforms(translucent_.id(), view);
  setSkyUniforms(translucent_.id(), view);
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_->translucentFramebuffer());
  glViewport(0, 0, gbuffer_->size().x, gbuffer_->size().y);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);  // tested against the opaque scene, never hiding each other
  glEnable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  // Premultiplied colour; alpha keeps the lighting pass's shadow term of the surface behind.
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  setMat4(translucent_.id(), "u_viewProjection", view.viewProjection);
  drawSections(translucent_.id(), visible_, meshes, MeshLayer::Translucent,
               {DrawOrder::FarthestFirst, glm::vec3(0.0f), false, true});
  if (props_ && propTranslucent_.id()) {
    const GLuint program = propTranslucent_.id();
    setLightingUniforms(program, view);
    setSkyUniforms(program, view);
    setMat4(program, "u_viewProjection", view.viewProjection);
    drawProps(program, *props_, visibleProps_, view.camera, AlphaMode::Blend, true);
  }
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

void DeferredRenderer::finalPass(GLuint framebuffer, glm::ivec2 size) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glBindTextureUnit(0, gbuffer_->scene());
  glProgramUniform1f(final_.id(), glGetUniformLocation(final_.id(), "u_exposure"), kExposure);
  glUseProgram(final_.id());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
}

void DeferredRenderer::outlinePass(const View& view, const WorldBox& box, GLuint framebuffer, glm::ivec2 size) {
  constexpr double kGrow = 0.002;  // Minecraft's: keeps the edges off the block's faces
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindTextureUnit(0, gbuffer_->depth());
  gl::setVec3(outline_.id(), "u_min", glm::vec3(box.min - kGrow - view.camera));
  gl::setVec3(outline_.id(), "u_max", glm::vec3(box.max + kGrow - view.camera));
  gl::setMat4(outline_.id(), "u_viewProjection", view.viewProjection);
  glUseProgram(outline_.id());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_LINES, 0, 24);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_BLEND);
}

void DeferredRenderer::debugPass(const View& view, GLuint framebuffer, glm::ivec2 size) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  gbuffer_->bindForReading();
  glProgramUniform2fv(debug_.id(), glGetUniformLocation(debug_.id(), "u_nearFar"), 1, glm::value_ptr(view.nearFar));
  glUseProgram(debug_.id());
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
}

std::size_t nonFinitePixels(const GBufferPixels& g) {
  std::size_t bad = 0;
  for (std::size_t p = 0; p < g.depth.size(); ++p) {
    bool finite = std::isfinite(g.depth[p]);
    for (int c = 0; c < 4; ++c) finite = finite && std::isfinite(g.scene[p][c]) && std::isfinite(g.normals[p][c]);
    bad += !finite;
  }
  return bad;
}

}  // namespace terrasol
