#include "pack_render/pack_renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <random>

#include "core/camera.h"
#include "core/day_cycle.h"
#include "core/error.h"
#include "core/lightmap.h"
#include "core/srgb.h"
#include "pack_render/pack_blend.h"
#include "pack_render/pack_entities.h"
#include "render/frame_graph.h"
#include "render/frustum.h"
#include "render/gl_slots.h"
#include "render/section_draw.h"
#include "render/shadow_receivers.h"
#include "shaderpack/block_properties.h"
#include "shaderpack/pack_draw_state.h"
#include "shaderpack/pack_macros.h"
#include "shaderpack/pack_uniforms.h"
#include "world/coords.h"

namespace terrasol {
namespace {

constexpr float kCutoutAlpha = 0.1f;        // OptiFine's alpha test for cutout geometry
constexpr float kCullAboveHorizon = 0.02f;  // the light's height (sine) from which casters are culled
constexpr float kTicksPerSecond = 20.0f;
constexpr double kFrameTimeWrap = 3600.0;  // frameTimeCounter wraps every hour

glm::vec3 srgbOf(glm::vec3 linear) {
  const glm::vec3 c = glm::clamp(linear, 0.0f, 1.0f);
  return {linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)};
}

}  // namespace

struct PackRenderer::Stage {
  StageKind kind;
  std::string slot;  // the program's name in the frame ("composite2", "gbuffers_water")
  std::unique_ptr<PackGlProgram> program;
  PackDrawState state;  // shaders.properties' alphaTest.<slot> and blend.<slot>
};

PackRenderer::PackRenderer(const ShaderPack& pack, const ShaderPreprocessor& shaders, const Atlas& atlas,
                           const TintPalette& tints, const std::vector<glm::vec2>& entityIds,
                           bool shadowCasterCulling)
    : packName_(pack.name()),
      blockTextures_(atlas, tints),
      gpuTimer_(!softwareRenderer()),
      shadowCasterCulling_(shadowCasterCulling) {
  const std::vector<ShaderDefine> macros = packMacros();
  if (const auto text = pack.text("shaders.properties"))
    properties_ = parseShaderProperties(*text, pack.displayName("shaders.properties"), PackMacros(macros));
  const PreprocessedShader blockReader = packVertexReader(shaders, PackInput::Block);
  const PreprocessedShader skyReader = packVertexReader(shaders, PackInput::Sky);
  const PreprocessedShader screenReader = packVertexReader(shaders, PackInput::Screen);

  const PackEvaluation atLoad{[](std::string_view) { return std::optional<PackValue>(); }, 0.0f};
  const auto enabled = [&](const std::string& name) {
    try {
      return properties_.programEnabled(name, atLoad);
    } catch (const Error&) {
      return true;  // it reads a uniform: OptiFine decides per frame; Terrasol keeps the program
    }
  };
  const auto add = [&](StageKind kind, const std::string& slot) {
    std::optional<PackProgram> files = enabled(slot) ? pack.resolve(slot) : std::nullopt;
    if (!enabled(slot)) {
      const std::string_view fallback = programFallback(slot);
      if (!fallback.empty()) files = pack.resolve(fallback);
    }
    if (!files) return;
    const bool screen =
        kind == StageKind::Deferred || kind == StageKind::Composite || kind == StageKind::Final;
    const bool sky = kind == StageKind::SkyBasic || kind == StageKind::SkyTextured;
    PackProgramSource source{
        &pack,           *files, screen ? PackInput::Screen : sky ? PackInput::Sky : PackInput::Block,
        !screen && !sky, macros, screen ? &screenReader : sky ? &skyReader : &blockReader};
    stages_.push_back(
        {kind, slot, std::make_unique<PackGlProgram>(source), packDrawState(properties_, slot)});
    names_.push_back(files->name == slot ? slot : slot + ": " + files->name);
  };
  add(StageKind::Shadow, "shadow");
  add(StageKind::SkyBasic, "gbuffers_skybasic");
  add(StageKind::SkyTextured, "gbuffers_skytextured");
  add(StageKind::Terrain, "gbuffers_terrain");
  for (const std::string& name : packProgramNames()) {
    if (name.starts_with("deferred") && pack.program(name)) add(StageKind::Deferred, name);
  }
  add(StageKind::Water, "gbuffers_water");
  for (const std::string& name : packProgramNames()) {
    if (name.starts_with("composite") && pack.program(name)) add(StageKind::Composite, name);
  }
  if (pack.program("final")) add(StageKind::Final, "final");

  std::vector<ProgramDirectives> directives;
  for (const Stage& s : stages_) directives.push_back(s.program->directives());
  settings_ = packSettings(directives, pack.name());
  usedBuffers_.set(0);
  for (const Stage& s : stages_) {
    if (s.kind != StageKind::Final && s.kind != StageKind::Shadow)
      for (int b : s.program->drawBuffers()) usedBuffers_.set(static_cast<std::size_t>(b));
    for (const PackSampler& sampler : s.program->samplers())
      if (sampler.texture == PackTexture::ColorTex)
        usedBuffers_.set(static_cast<std::size_t>(sampler.buffer));
  }
  // Terrasol's own keys: the buffers --report reads the shadow term and the normal from.
  const auto reportBuffer = [&](const char* key) -> std::optional<int> {
    const ShaderProperties::Entry* e = properties_.find(key);
    if (!e) return std::nullopt;
    for (int b = 0; b < kPackColorBuffers; ++b)
      if (e->value == "colortex" + std::to_string(b) && usedBuffers_[static_cast<std::size_t>(b)]) return b;
    throw Error(e->where + ": " + key + ": '" + e->value + "' is not a colortexN the pack draws");
  };
  reportShadow_ = reportBuffer("terrasol.report.shadow");
  reportNormal_ = reportBuffer("terrasol.report.normal");
  // texture.noise: an image in the pack in place of the random one.
  std::optional<Image> noiseImage;
  if (const ShaderProperties::Entry* e = properties_.find("texture.noise")) {
    const std::string path = e->value.starts_with("/") ? e->value.substr(1) : e->value;
    const std::optional<std::string> bytes = pack.text(path);
    if (!bytes) throw Error(e->where + ": texture.noise: no file " + pack.displayName(path));
    noiseImage = decodeImage(std::vector<std::uint8_t>(bytes->begin(), bytes->end()), pack.displayName(path));
  }
  drawSun_ = packSwitch(properties_, "sun", true);
  drawMoon_ = packSwitch(properties_, "moon", true);
  const bool oldLighting = packSwitch(properties_, "oldLighting", false);
  for (const Stage& s : stages_) s.program->setOldLighting(oldLighting);
  textures_ = std::make_unique<PackTextures>(blockTextures_, settings_, entityIds, noiseImage);
  // A pack without a shadow program pays for no map.
  shadowMaps_ = std::make_unique<PackShadowMaps>(
      stageOf(StageKind::Shadow) ? std::clamp(settings_.shadowMapResolution, 16, 8192) : 1);
}

PackRenderer::~PackRenderer() = default;

std::vector<std::string> PackRenderer::unknownUniforms() const {
  std::vector<std::string> out;
  for (const Stage& s : stages_)
    for (const std::string& u : s.program->unknownUniforms()) out.push_back(s.slot + ": " + u);
  return out;
}

struct PackRenderer::FrameState {
  const SectionMeshes& meshes;
  GLuint framebuffer;
  glm::ivec2 size, targetSize;  // the buffers' (at the render scale) and the target's
  PackView view;
  PackMatrices world, light, screen;
  std::vector<VisibleSection> visible;  // in the camera's frustum
};

const PackRenderer::Stage* PackRenderer::stageOf(StageKind kind) const {
  const auto it =
      std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return s.kind == kind; });
  return it == stages_.end() ? nullptr : &*it;
}

PackView PackRenderer::viewFor(const FrameInputs& inputs, glm::ivec2 size, float sunPathRotation,
                               const DayState& day) {
  PackView view;
  view.camera = inputs.cameraPosition;
  view.lookAt = inputs.cameraLookAt;
  view.up = inputs.cameraUp;
  view.fovDegrees = inputs.fovDegrees;
  view.ticks = inputs.ticks;
  view.sunPathRotation = sunPathRotation;
  view.size = size;
  view.viewDistance = inputs.viewDistance;
  // Time from the world's ticks, so a frame is the same whenever it is drawn.
  view.frameTime =
      frameCounter_ == 0 ? 0.0f : static_cast<float>(inputs.ticks - lastTicks_) / kTicksPerSecond;
  view.frameTimeCounter =
      static_cast<float>(std::fmod(static_cast<double>(inputs.ticks) / kTicksPerSecond, kFrameTimeWrap));
  view.frameCounter = frameCounter_++;
  lastTicks_ = inputs.ticks;
  view.underWater = inputs.underWater.has_value();
  view.eyeLight = inputs.eyeLight;
  view.fogColor = srgbOf(day.fogColor);
  view.skyColor = srgbOf(day.skyZenith);
  return view;
}

void PackRenderer::render(const FrameInputs& inputs, const SectionMeshes& meshes, GLuint framebuffer,
                          glm::ivec2 targetSize, std::vector<PassTiming>* timings) {
  if (targetSize.x <= 0 || targetSize.y <= 0) return;
  stats_ = {};
  // The buffers at the render scale (dynamic resolution); the final program, or the copy out, scales
  // the picture up to the target.
  const glm::ivec2 size = scaledRenderSize(targetSize, inputs.renderScale);
  if (!targets_ || targets_->size() != size) targets_.emplace(size, settings_, usedBuffers_);
  blockTextures_.update(inputs.ticks);

  // The pack's sun path, else the world's: Terrasol tilts towards +z for positive angles, packs
  // (vanilla's sky) towards -z.
  const float sunPathRotation = settings_.sunPathRotation.value_or(-inputs.sunPathRotation);
  const DayState day = dayStateAt(inputs.ticks, -sunPathRotation);
  FrameState frame{meshes, framebuffer, size, targetSize, viewFor(inputs, size, sunPathRotation, day),
                   {},     {},          {},   {}};
  uniforms_ = packFrameUniforms(frame.view, settings_, history_);
  evaluateCustoms(properties_, uniforms_, frame.view.frameTime);
  for (Stage& s : stages_) s.program->setUniforms(uniforms_);

  const PackCamera camera = packCamera(frame.view);
  lastModelView_ = camera.modelView;
  const glm::mat4 viewProjection = camera.projection * camera.modelView;
  const glm::vec3 toLight =
      glm::inverse(glm::mat3(camera.modelView)) * std::get<glm::vec3>(*uniforms_.find("shadowLightPosition"));
  geometry_ = {frame.view.camera,
               viewProjection,
               glm::inverse(viewProjection),
               glm::normalize(toLight),
               stageOf(StageKind::Shadow) && reportShadow_ && reportNormal_,
               0.0f};  // the pack places its own map: no texel to move it by
  const glm::mat4 lightmapMatrix =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f / 32.0f)), glm::vec3(1.0f / 256.0f));
  frame.world = {camera.modelView, camera.projection, glm::mat4(1.0f), lightmapMatrix};
  frame.light = {std::get<glm::mat4>(*uniforms_.find("shadowModelView")),
                 std::get<glm::mat4>(*uniforms_.find("shadowProjection")), glm::mat4(1.0f), lightmapMatrix};
  frame.screen = {glm::mat4(1.0f), glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f), glm::mat4(1.0f),
                  glm::mat4(1.0f)};
  textures_->updateLightmap(buildLightmap(day, inputs.ticks));
  sky_.update(frame.view.skyColor, packSkyRotation(packTimeAt(inputs.ticks), sunPathRotation));
  frame.visible =
      sectionsInside(frustumPlanes(viewProjection), frame.view.camera, meshes, &stats_.sectionsCulled);
  stats_.sectionsDrawn = static_cast<int>(frame.visible.size());

  FrameGraph graph;
  PassClock clock(timings, gpuTimer_);
  const FrameGraph::Resource shadowMaps = graph.transient("shadow maps");
  const FrameGraph::Resource buffers = graph.transient("buffers");
  const FrameGraph::Resource target = graph.import("target");
  if (const Stage* shadow = stageOf(StageKind::Shadow)) {
    graph.add(
        "shadow", [&](FrameGraph::Builder& b) { b.write(shadowMaps); },
        [this, shadow, &frame, casters = shadowCasters(frame)] { drawShadow(*shadow, frame, casters); });
  }
  graph.add(
      "sky", [&](FrameGraph::Builder& b) { b.write(buffers); }, [&] { drawSky(frame); });
  const Stage* terrain = stageOf(StageKind::Terrain);
  graph.add(
      "terrain",
      [&](FrameGraph::Builder& b) {
        if (!terrain) return b.skip("the pack has no terrain program");
        if (b.written(shadowMaps)) b.read(shadowMaps);
        b.read(buffers);
        b.write(buffers);
      },
      [&] { drawTerrain(*terrain, frame); });
  const auto addScreen = [&](const Stage& s) {
    graph.add(
        s.slot,
        [&](FrameGraph::Builder& b) {
          if (b.written(shadowMaps)) b.read(shadowMaps);
          b.read(buffers);
          b.write(s.kind == StageKind::Final ? target : buffers);
        },
        [&] { drawScreen(s, frame); });
  };
  for (const Stage& s : stages_)
    if (s.kind == StageKind::Deferred) addScreen(s);
  graph.add(
      "water",
      [&](FrameGraph::Builder& b) {
        b.read(buffers);
        b.write(buffers);
      },
      [&] { drawWater(stageOf(StageKind::Water), frame); });
  for (const Stage& s : stages_)
    if (s.kind == StageKind::Composite) addScreen(s);
  if (const Stage* final = stageOf(StageKind::Final)) {
    addScreen(*final);
  } else {
    graph.add(
        "final",
        [&](FrameGraph::Builder& b) {
          b.read(buffers);
          b.write(target);
        },
        [&] {
          // No final program: colortex0 is the picture (OptiFine copies it).
          targets_->bindRead(0);
          glBlitNamedFramebuffer(targets_->framebuffer(), framebuffer, 0, 0, size.x, size.y, 0, 0,
                                 targetSize.x, targetSize.y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        });
  }
  graph.output(target);
  graph.execute([&](const std::string& pass) { clock.lap(pass); });
  for (const FrameGraph::Skipped& s : graph.skipped()) stats_.passesSkipped.push_back({s.pass, s.why});

  // The picture is opaque, as a window shows it, whatever alpha the pack left (mipmapped cutout edges).
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  textures_->unbindSamplers();
}

// Casters whose shadow can fall on nothing in view are left out (not near the horizon, where the swept
// boxes grow without bound and the light may change sides).
std::vector<VisibleSection> PackRenderer::shadowCasters(const FrameState& frame) {
  const PackView& view = frame.view;
  std::vector<VisibleSection> casters = sectionsInside(
      frustumPlanes(frame.light.projection * frame.light.modelView), view.camera, frame.meshes);
  if (shadowCasterCulling_ && geometry_.toLight.y > kCullAboveHorizon) {
    ViewCone cone;
    cone.eye = view.camera;
    cone.forward = glm::vec3(glm::normalize(view.lookAt - view.camera));
    cone.up = glm::vec3(view.up);
    cone.fovDegrees = view.fovDegrees;
    cone.aspect = static_cast<float>(frame.size.x) / static_cast<float>(frame.size.y);
    cone.farPlane = packFarPlane(view);
    cone.floorY = kMinY;
    const ShadowReceivers receivers(cone);
    const auto before = casters.size();
    std::erase_if(casters, [&](const VisibleSection& v) {
      const glm::dvec3 lo = view.camera + glm::dvec3(v.offset);
      return !receivers.mayShade(lo, lo + glm::dvec3(16.0), geometry_.toLight);
    });
    stats_.shadowCastersOffView = static_cast<int>(before - casters.size());
  }
  stats_.shadowCasters = static_cast<int>(casters.size());
  return casters;
}

void PackRenderer::drawBlocks(const Stage& stage, const FrameState& frame,
                              const std::vector<VisibleSection>& sections, MeshLayer layer, DrawOrder order,
                              FrameStats* stats) {
  PackGlProgram& program = *stage.program;
  program.setAlphaTest(stage.state.alphaTestRef.value_or(layer == MeshLayer::Cutout ? kCutoutAlpha : 0.0f));
  program.setRenderStage(static_cast<int>(layer == MeshLayer::Opaque   ? RenderStage::TerrainSolid
                                          : layer == MeshLayer::Cutout ? RenderStage::TerrainCutout
                                                                       : RenderStage::TerrainTranslucent));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slots::kStoragePackEntities, textures_->entities());
  SectionDraw how;
  how.order = order;
  how.stats = stats;
  how.view = SectionMeshes::View::Light;  // faces, not merged quads: a pack's UVs stay in their tile
  drawSections(program.id(), program.section(), blockTextures_, sections, frame.meshes, layer, how);
  if (stats) stats->quadsDrawn += static_cast<std::int64_t>(quadsIn(sections, layer));
}

void PackRenderer::drawShadow(const Stage& shadow, const FrameState& frame,
                              const std::vector<VisibleSection>& casters) {
  PackGlProgram& program = *shadow.program;
  shadowMaps_->begin();
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  program.setMatrices(frame.light);
  glUseProgram(program.id());
  textures_->bind(program, textures_->atlas(), *targets_, *shadowMaps_);
  shadowMaps_->bindPass(0, program.drawBuffers());
  drawBlocks(shadow, frame, casters, MeshLayer::Opaque, DrawOrder::NearestFirst, nullptr);
  drawBlocks(shadow, frame, casters, MeshLayer::Cutout, DrawOrder::NearestFirst, nullptr);
  shadowMaps_->copyOpaque();
  shadowMaps_->bindPass(1, program.drawBuffers());
  drawBlocks(shadow, frame, casters, MeshLayer::Translucent, DrawOrder::NearestFirst, nullptr);
}

void PackRenderer::drawSky(const FrameState& frame) {
  targets_->clear(frame.view.fogColor);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  if (const Stage* basic = stageOf(StageKind::SkyBasic)) {
    PackGlProgram& p = *basic->program;
    targets_->bindDraw(p.drawBuffers(), false, false);
    glUseProgram(p.id());
    p.setMatrices(frame.world);
    p.setRenderStage(static_cast<int>(RenderStage::Sky));
    textures_->bind(p, 0, *targets_, *shadowMaps_);
    applyBlend(basic->state, nullptr);
    sky_.drawSky();
  }
  if (const Stage* textured = stageOf(StageKind::SkyTextured)) {
    PackGlProgram& p = *textured->program;
    targets_->bindDraw(p.drawBuffers(), false, false);
    glUseProgram(p.id());
    p.setMatrices(frame.world);
    textures_->bind(p, 0, *targets_, *shadowMaps_);
    // Vanilla adds the sun and moon onto the sky; shaders.properties may leave either out.
    applyBlend(textured->state, &kAddedBlend);
    if (drawSun_) {
      p.setRenderStage(static_cast<int>(RenderStage::Sun));
      sky_.drawSun(packUnit(0));
    }
    if (drawMoon_) {
      p.setRenderStage(static_cast<int>(RenderStage::Moon));
      sky_.drawMoon(packUnit(0));
    }
    glDisable(GL_BLEND);
  }
  glDepthMask(GL_TRUE);
}

void PackRenderer::drawTerrain(const Stage& terrain, const FrameState& frame) {
  PackGlProgram& p = *terrain.program;
  targets_->bindDraw(p.drawBuffers(), false, true);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  applyBlend(terrain.state, nullptr);
  glUseProgram(p.id());
  p.setMatrices(frame.world);
  textures_->bind(p, textures_->atlas(), *targets_, *shadowMaps_);
  drawBlocks(terrain, frame, frame.visible, MeshLayer::Opaque, DrawOrder::NearestFirst, &stats_);
  drawBlocks(terrain, frame, frame.visible, MeshLayer::Cutout, DrawOrder::NearestFirst, &stats_);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
}

void PackRenderer::drawWater(const Stage* water, const FrameState& frame) {
  targets_->keepOpaqueDepth();
  if (!water || quadsIn(frame.visible, MeshLayer::Translucent) == 0) return;
  PackGlProgram& p = *water->program;
  targets_->bindDraw(p.drawBuffers(), false, true);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  applyBlend(water->state, &kTranslucentBlend);
  glUseProgram(p.id());
  p.setMatrices(frame.world);
  textures_->bind(p, textures_->atlas(), *targets_, *shadowMaps_);
  drawBlocks(*water, frame, frame.visible, MeshLayer::Translucent, DrawOrder::FarthestFirst, &stats_);
  glDisable(GL_BLEND);
}

void PackRenderer::drawScreen(const Stage& stage, const FrameState& frame) {
  PackGlProgram& program = *stage.program;
  for (int b = 0; b < kPackColorBuffers; ++b) {
    const std::string n = "colortex" + std::to_string(b) + "MipmapEnabled";
    if (program.directives().flag(n).value_or(false)) targets_->generateMipmaps(b);
  }
  const bool toTarget = stage.kind == StageKind::Final;
  if (toTarget) {
    glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
    glViewport(0, 0, frame.targetSize.x, frame.targetSize.y);
  } else {
    targets_->bindDraw(program.drawBuffers(), true, false);
  }
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glUseProgram(program.id());
  program.setMatrices(frame.screen);
  textures_->bind(program, 0, *targets_, *shadowMaps_);
  glBindVertexArray(textures_->emptyVertexArray());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  if (toTarget) return;
  // The buffers it wrote flip, unless the pack says otherwise (flip.<program>.<buffer>).
  const auto& written = program.drawBuffers();
  for (int b = 0; b < kPackColorBuffers; ++b) {
    bool flip = std::find(written.begin(), written.end(), b) != written.end();
    if (const auto* e = properties_.find("flip." + stage.slot + ".colortex" + std::to_string(b)))
      flip = e->value == "true";
    if (flip && targets_->has(b)) targets_->flip(b);
  }
}

std::unique_ptr<PackRenderer> loadShaderPack(const std::filesystem::path& path,
                                             const ShaderPreprocessor& shaders, const BlockRegistry& blocks,
                                             const BlockMeshTable& table, const Atlas& atlas,
                                             const TintPalette& tints, bool shadowCasterCulling) {
  const ShaderPack pack = ShaderPack::open(path);
  BlockIdMap ids;
  if (const auto text = pack.text("block.properties"))
    ids = parseBlockProperties(*text, pack.displayName("block.properties"), PackMacros(packMacros()), blocks);
  return std::make_unique<PackRenderer>(
      pack, shaders, atlas, tints, packEntityIds(ids, table, atlas.textures.size()), shadowCasterCulling);
}

}  // namespace terrasol
