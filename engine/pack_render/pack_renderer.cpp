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
#include "core/octahedral.h"
#include "core/srgb.h"
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

enum class StageKind { Shadow, SkyBasic, SkyTextured, Terrain, Deferred, Water, Composite, Final };

constexpr float kCutoutAlpha = 0.1f;        // OptiFine's alpha test for cutout geometry
constexpr float kCullAboveHorizon = 0.02f;  // the light's height (sine) from which casters are culled
constexpr float kTicksPerSecond = 20.0f;
constexpr double kFrameTimeWrap = 3600.0;  // frameTimeCounter wraps every hour

GLuint unitOf(int optifineUnit) {
  return static_cast<GLuint>(slots::kUnitPackBase + optifineUnit);
}

gl::Texture texture2d(GLenum format, glm::ivec2 size, GLenum filter, GLenum wrap = GL_CLAMP_TO_EDGE) {
  gl::Texture t = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, size.x, size.y);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  return t;
}

gl::Sampler samplerFor(bool compare, bool nearest) {
  gl::Sampler s = gl::Sampler::create();
  const GLint filter = nearest ? GL_NEAREST : GL_LINEAR;
  glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (compare) {
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  return s;
}

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

namespace {

GLenum blendFactor(const std::string& name) {
  static const std::map<std::string, GLenum, std::less<>> kFactors = {
      {"ZERO", GL_ZERO},
      {"ONE", GL_ONE},
      {"SRC_COLOR", GL_SRC_COLOR},
      {"ONE_MINUS_SRC_COLOR", GL_ONE_MINUS_SRC_COLOR},
      {"DST_COLOR", GL_DST_COLOR},
      {"ONE_MINUS_DST_COLOR", GL_ONE_MINUS_DST_COLOR},
      {"SRC_ALPHA", GL_SRC_ALPHA},
      {"ONE_MINUS_SRC_ALPHA", GL_ONE_MINUS_SRC_ALPHA},
      {"DST_ALPHA", GL_DST_ALPHA},
      {"ONE_MINUS_DST_ALPHA", GL_ONE_MINUS_DST_ALPHA},
      {"SRC_ALPHA_SATURATE", GL_SRC_ALPHA_SATURATE},
  };
  return kFactors.at(name);  // packDrawState admits only these
}

// The stage's blending: the pack's blend.<program>, else `fallback` (src, dst, srcAlpha, dstAlpha), or
// none without one.
void applyBlend(const PackDrawState& state, const std::array<GLenum, 4>* fallback) {
  if (state.blend && !state.blend->enabled) return glDisable(GL_BLEND);
  if (state.blend) {
    const auto& f = state.blend->factors;
    glEnable(GL_BLEND);
    glBlendFuncSeparate(blendFactor(f[0]), blendFactor(f[1]), blendFactor(f[2]), blendFactor(f[3]));
    return;
  }
  if (!fallback) return glDisable(GL_BLEND);
  glEnable(GL_BLEND);
  glBlendFuncSeparate((*fallback)[0], (*fallback)[1], (*fallback)[2], (*fallback)[3]);
}

constexpr std::array<GLenum, 4> kTranslucentBlend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE,
                                                     GL_ONE_MINUS_SRC_ALPHA};
constexpr std::array<GLenum, 4> kAddedBlend = {GL_SRC_ALPHA, GL_ONE, GL_ONE, GL_ZERO};  // sun and moon

}  // namespace

// What the pack's samplers read besides its buffers.
struct PackRenderer::Textures {
  Textures(const BlockTextures& blocks, int shadowResolution, int noiseResolution,
           const std::vector<glm::vec2>& entityIds, const std::optional<Image>& noiseImage)
      : atlas(gl::TextureView::create(GL_TEXTURE_2D, blocks.atlas().albedo(), GL_RGBA8, 0u, levelsOf(blocks),
                                      0u, 1u)),
        lightmap(texture2d(GL_RGBA8, glm::ivec2(Lightmap::kSize), GL_LINEAR)),
        noise(noiseImage ? texture2d(GL_RGBA8, {noiseImage->width, noiseImage->height}, GL_LINEAR, GL_REPEAT)
                         : texture2d(GL_RGB8, glm::ivec2(noiseResolution), GL_LINEAR, GL_REPEAT)),
        entities(gl::Buffer::create()),
        shadowResolution(shadowResolution) {
    // The atlas as packs sample it: its sRGB texels as stored, not decoded.
    glTextureParameteri(atlas.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
    glTextureParameteri(atlas.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (noiseImage) {
      glTextureSubImage2D(noise.id(), 0, 0, 0, noiseImage->width, noiseImage->height, GL_RGBA,
                          GL_UNSIGNED_BYTE, noiseImage->rgba.data());
    } else {
      // Random RGB, the same every run (Iris fills it from a seeded generator too).
      std::vector<std::uint8_t> texels(static_cast<std::size_t>(noiseResolution * noiseResolution * 3));
      std::mt19937 random(0);
      for (std::uint8_t& t : texels) t = static_cast<std::uint8_t>(random() & 0xff);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTextureSubImage2D(noise.id(), 0, 0, 0, noiseResolution, noiseResolution, GL_RGB, GL_UNSIGNED_BYTE,
                          texels.data());
      glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }
    std::vector<glm::vec2> ids = entityIds;
    if (ids.empty()) ids.push_back(glm::vec2(-1.0f));
    glNamedBufferStorage(entities.id(), static_cast<GLsizeiptr>(ids.size() * sizeof(glm::vec2)), ids.data(),
                         0);
    const glm::ivec2 shadowSize(shadowResolution);
    for (gl::Texture& t : shadowDepth) t = texture2d(GL_DEPTH_COMPONENT32F, shadowSize, GL_NEAREST);
    for (gl::Texture& t : shadowColour) t = texture2d(GL_RGBA8, shadowSize, GL_LINEAR);
    for (gl::Framebuffer& f : shadowFramebuffers) f = gl::Framebuffer::create();
    for (int i = 0; i < 2; ++i) {
      glNamedFramebufferTexture(shadowFramebuffers[i].id(), GL_DEPTH_ATTACHMENT, shadowDepth[1 - i].id(), 0);
      for (int c = 0; c < 2; ++c) {
        glNamedFramebufferTexture(shadowFramebuffers[i].id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(c),
                                  shadowColour[c].id(), 0);
      }
    }
  }
  static GLuint levelsOf(const BlockTextures& blocks) {
    GLint levels = 1;
    glGetTextureParameteriv(blocks.atlas().albedo(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    return static_cast<GLuint>(std::max(levels, 1));
  }

  gl::TextureView atlas;
  gl::Texture lightmap, noise;
  gl::Buffer entities;
  int shadowResolution;
  std::array<gl::Texture, 2> shadowDepth;             // shadowtex0 (everything), shadowtex1 (opaque)
  std::array<gl::Texture, 2> shadowColour;            // shadowcolor0, shadowcolor1
  std::array<gl::Framebuffer, 2> shadowFramebuffers;  // drawing into shadowtex1, then shadowtex0
  gl::Sampler compareLinear = samplerFor(true, false), compareNearest = samplerFor(true, true);
  gl::Sampler nearest = samplerFor(false, true), linear = samplerFor(false, false);
  gl::VertexArray empty = gl::VertexArray::create();
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
  textures_ = std::make_unique<Textures>(blockTextures_, std::clamp(settings_.shadowMapResolution, 16, 8192),
                                         std::clamp(settings_.noiseTextureResolution, 1, 4096), entityIds,
                                         noiseImage);
}

PackRenderer::~PackRenderer() = default;

std::vector<std::string> PackRenderer::unknownUniforms() const {
  std::vector<std::string> out;
  for (const Stage& s : stages_)
    for (const std::string& u : s.program->unknownUniforms()) out.push_back(s.slot + ": " + u);
  return out;
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

  // The frame's uniforms.
  // The pack's sun path, else the world's: Terrasol tilts towards +z for positive angles, packs
  // (vanilla's sky) towards -z.
  const float sunPathRotation = settings_.sunPathRotation.value_or(-inputs.sunPathRotation);
  const DayState day = dayStateAt(inputs.ticks, -sunPathRotation);
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
  view.atlasSize = glm::ivec2(0);
  uniforms_ = packFrameUniforms(view, settings_, history_);
  evaluateCustoms(properties_, uniforms_, view.frameTime);
  for (Stage& s : stages_) s.program->setUniforms(uniforms_);

  const PackCamera camera = packCamera(view);
  const PackTime time = packTimeAt(inputs.ticks);
  lastModelView_ = camera.modelView;
  const bool hasShadow =
      std::any_of(stages_.begin(), stages_.end(), [](const Stage& s) { return s.kind == StageKind::Shadow; });
  {
    const glm::vec3 toLight = glm::inverse(glm::mat3(camera.modelView)) *
                              std::get<glm::vec3>(*uniforms_.find("shadowLightPosition"));
    const glm::mat4 viewProjection = camera.projection * camera.modelView;
    geometry_ = {view.camera,
                 viewProjection,
                 glm::inverse(viewProjection),
                 glm::normalize(toLight),
                 hasShadow && reportShadow_ && reportNormal_,
                 0.0f};  // the pack places its own map: no texel to move it by
  }
  const glm::mat4 shadowModelView = std::get<glm::mat4>(*uniforms_.find("shadowModelView"));
  const glm::mat4 shadowProjection = std::get<glm::mat4>(*uniforms_.find("shadowProjection"));
  const glm::mat4 lightmapMatrix =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f / 32.0f)), glm::vec3(1.0f / 256.0f));
  const PackMatrices world{camera.modelView, camera.projection, glm::mat4(1.0f), lightmapMatrix};
  const PackMatrices light{shadowModelView, shadowProjection, glm::mat4(1.0f), lightmapMatrix};
  const PackMatrices screen{glm::mat4(1.0f), glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f), glm::mat4(1.0f),
                            glm::mat4(1.0f)};

  // The lightmap: vanilla's 16x16 colours for this moment, as sRGB.
  {
    const Lightmap lightmap = buildLightmap(day, inputs.ticks);
    std::vector<std::uint8_t> texels;
    for (const glm::vec3& c : lightmap.texels) {
      const glm::vec3 s = srgbOf(c) * 255.0f;
      texels.insert(texels.end(),
                    {static_cast<std::uint8_t>(std::lround(s.r)), static_cast<std::uint8_t>(std::lround(s.g)),
                     static_cast<std::uint8_t>(std::lround(s.b)), 255});
    }
    glTextureSubImage2D(textures_->lightmap.id(), 0, 0, 0, Lightmap::kSize, Lightmap::kSize, GL_RGBA,
                        GL_UNSIGNED_BYTE, texels.data());
  }
  sky_.update(view.skyColor, packSkyRotation(time, sunPathRotation));

  // Culling: the camera's frustum, and the shadow camera's box.
  const std::vector<VisibleSection> visible = sectionsInside(
      frustumPlanes(camera.projection * camera.modelView), view.camera, meshes, &stats_.sectionsCulled);
  stats_.sectionsDrawn = static_cast<int>(visible.size());

  const auto bindSamplers = [&](const PackGlProgram& program, GLuint drawnTexture) {
    const Textures& t = *textures_;
    for (const PackSampler& s : program.samplers()) {
      GLuint texture = 0;
      GLuint sampler = 0;
      const auto shadowSampler = [&](bool nearestWanted) {
        return s.shadow ? (nearestWanted ? t.compareNearest.id() : t.compareLinear.id())
                        : (nearestWanted ? t.nearest.id() : t.linear.id());
      };
      switch (s.texture) {
        case PackTexture::Texture:
          texture = drawnTexture;
          break;
        case PackTexture::Lightmap:
          texture = t.lightmap.id();
          break;
        case PackTexture::Normals:
          texture = blockTextures_.atlas().normal();
          break;
        case PackTexture::Specular:
          texture = blockTextures_.atlas().specular();
          break;
        case PackTexture::ShadowTex0:
        case PackTexture::ShadowTex1: {
          const int i = s.texture == PackTexture::ShadowTex0 ? 0 : 1;
          texture = t.shadowDepth[static_cast<std::size_t>(i)].id();
          sampler = shadowSampler(settings_.shadowtexNearest[static_cast<std::size_t>(i)] ||
                                  (s.shadow && !settings_.shadowHardwareFiltering));
          break;
        }
        case PackTexture::ShadowColor0:
        case PackTexture::ShadowColor1: {
          const int i = s.texture == PackTexture::ShadowColor0 ? 0 : 1;
          texture = t.shadowColour[static_cast<std::size_t>(i)].id();
          sampler =
              settings_.shadowcolorNearest[static_cast<std::size_t>(i)] ? t.nearest.id() : t.linear.id();
          break;
        }
        case PackTexture::DepthTex0:
          texture = targets_->depth(0);
          break;
        case PackTexture::DepthTex1:
        case PackTexture::DepthTex2:
          texture = targets_->depth(1);
          break;
        case PackTexture::Noise:
          texture = t.noise.id();
          break;
        case PackTexture::ColorTex:
          texture = targets_->has(s.buffer) ? targets_->main(s.buffer) : 0;
          break;
      }
      if (s.texture == PackTexture::Texture && drawnTexture == 0) continue;  // bound by the draw
      glBindTextureUnit(unitOf(s.unit), texture);
      glBindSampler(unitOf(s.unit), sampler);
    }
  };
  const auto drawTerrain = [&](const Stage& stage, const std::vector<VisibleSection>& sections,
                               MeshLayer layer, DrawOrder order, FrameStats* stats) {
    PackGlProgram& program = *stage.program;
    program.setAlphaTest(stage.state.alphaTestRef.value_or(layer == MeshLayer::Cutout ? kCutoutAlpha : 0.0f));
    program.setRenderStage(static_cast<int>(layer == MeshLayer::Opaque   ? RenderStage::TerrainSolid
                                            : layer == MeshLayer::Cutout ? RenderStage::TerrainCutout
                                                                         : RenderStage::TerrainTranslucent));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slots::kStoragePackEntities, textures_->entities.id());
    SectionDraw how;
    how.order = order;
    how.stats = stats;
    how.view = SectionMeshes::View::Light;  // faces, not merged quads: a pack's UVs stay in their tile
    drawSections(program.id(), program.section(), blockTextures_, sections, meshes, layer, how);
    if (stats) stats->quadsDrawn += static_cast<std::int64_t>(quadsIn(sections, layer));
  };
  const auto screenPass = [&](Stage& s) {
    PackGlProgram& program = *s.program;
    for (int b = 0; b < kPackColorBuffers; ++b) {
      const std::string n = "colortex" + std::to_string(b) + "MipmapEnabled";
      if (program.directives().flag(n).value_or(false)) targets_->generateMipmaps(b);
    }
    const bool toTarget = s.kind == StageKind::Final;
    if (toTarget) {
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
      glViewport(0, 0, targetSize.x, targetSize.y);
    } else {
      targets_->bindDraw(program.drawBuffers(), true, false);
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(program.id());
    program.setMatrices(screen);
    bindSamplers(program, 0);
    glBindVertexArray(textures_->empty.id());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    if (toTarget) return;
    // The buffers it wrote flip, unless the pack says otherwise (flip.<program>.<buffer>).
    for (int b = 0; b < kPackColorBuffers; ++b) {
      const auto& written = program.drawBuffers();
      bool flip = std::find(written.begin(), written.end(), b) != written.end();
      if (const auto* e = properties_.find("flip." + s.slot + ".colortex" + std::to_string(b)))
        flip = e->value == "true";
      if (flip && targets_->has(b)) targets_->flip(b);
    }
  };
  const auto stageOf = [&](StageKind kind) -> Stage* {
    const auto it =
        std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return s.kind == kind; });
    return it == stages_.end() ? nullptr : &*it;
  };

  FrameGraph graph;
  PassClock clock(timings, gpuTimer_);
  const FrameGraph::Resource shadowMaps = graph.transient("shadow maps");
  const FrameGraph::Resource buffers = graph.transient("buffers");
  const FrameGraph::Resource target = graph.import("target");

  if (Stage* shadow = stageOf(StageKind::Shadow)) {
    std::vector<VisibleSection> casters =
        sectionsInside(frustumPlanes(shadowProjection * shadowModelView), view.camera, meshes);
    // Casters whose shadow can fall on nothing in view are left out (not near the horizon, where the
    // swept boxes grow without bound and the light may change sides).
    if (shadowCasterCulling_ && geometry_.toLight.y > kCullAboveHorizon) {
      ViewCone cone;
      cone.eye = view.camera;
      cone.forward = glm::vec3(glm::normalize(view.lookAt - view.camera));
      cone.up = glm::vec3(view.up);
      cone.fovDegrees = view.fovDegrees;
      cone.aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
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
    graph.add(
        "shadow", [&](FrameGraph::Builder& b) { b.write(shadowMaps); },
        [&, shadow, casters] {
          PackGlProgram& program = *shadow->program;
          Textures& t = *textures_;
          std::vector<GLenum> draw;
          for (int i : program.drawBuffers())
            draw.push_back(i < 2 ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i) : GL_NONE);
          const glm::vec4 white(1.0f);
          const float far = 1.0f;
          for (const gl::Texture& c : t.shadowColour) glClearTexImage(c.id(), 0, GL_RGBA, GL_FLOAT, &white);
          for (const gl::Texture& d : t.shadowDepth)
            glClearTexImage(d.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
          glViewport(0, 0, t.shadowResolution, t.shadowResolution);
          glEnable(GL_DEPTH_TEST);
          glDepthFunc(GL_LEQUAL);
          glDepthMask(GL_TRUE);
          glDisable(GL_BLEND);
          glDisable(GL_CULL_FACE);
          program.setMatrices(light);
          glUseProgram(program.id());
          bindSamplers(program, t.atlas.id());
          for (int pass = 0; pass < 2; ++pass) {
            glNamedFramebufferDrawBuffers(t.shadowFramebuffers[pass].id(), static_cast<GLsizei>(draw.size()),
                                          draw.data());
            glBindFramebuffer(GL_FRAMEBUFFER, t.shadowFramebuffers[pass].id());
            if (pass == 0) {
              drawTerrain(*shadow, casters, MeshLayer::Opaque, DrawOrder::NearestFirst, nullptr);
              drawTerrain(*shadow, casters, MeshLayer::Cutout, DrawOrder::NearestFirst, nullptr);
              // shadowtex1 holds the opaque; shadowtex0 starts from it and adds the translucent.
              glCopyImageSubData(t.shadowDepth[1].id(), GL_TEXTURE_2D, 0, 0, 0, 0, t.shadowDepth[0].id(),
                                 GL_TEXTURE_2D, 0, 0, 0, 0, t.shadowResolution, t.shadowResolution, 1);
            } else {
              drawTerrain(*shadow, casters, MeshLayer::Translucent, DrawOrder::NearestFirst, nullptr);
            }
          }
        });
  }

  graph.add(
      "sky", [&](FrameGraph::Builder& b) { b.write(buffers); },
      [&] {
        targets_->clear(view.fogColor);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        const PackMatrices skyMatrices{camera.modelView, camera.projection, glm::mat4(1.0f), lightmapMatrix};
        if (Stage* basic = stageOf(StageKind::SkyBasic)) {
          PackGlProgram& p = *basic->program;
          targets_->bindDraw(p.drawBuffers(), false, false);
          glUseProgram(p.id());
          p.setMatrices(skyMatrices);
          p.setRenderStage(static_cast<int>(RenderStage::Sky));
          bindSamplers(p, 0);
          applyBlend(basic->state, nullptr);
          sky_.drawSky();
        }
        if (Stage* textured = stageOf(StageKind::SkyTextured)) {
          PackGlProgram& p = *textured->program;
          targets_->bindDraw(p.drawBuffers(), false, false);
          glUseProgram(p.id());
          p.setMatrices(skyMatrices);
          bindSamplers(p, 0);
          // Vanilla adds the sun and moon onto the sky; shaders.properties may leave either out.
          applyBlend(textured->state, &kAddedBlend);
          const GLuint unit = unitOf(0);
          if (drawSun_) {
            p.setRenderStage(static_cast<int>(RenderStage::Sun));
            sky_.drawSun(unit);
          }
          if (drawMoon_) {
            p.setRenderStage(static_cast<int>(RenderStage::Moon));
            sky_.drawMoon(unit);
          }
          glDisable(GL_BLEND);
        }
        glDepthMask(GL_TRUE);
      });

  Stage* terrain = stageOf(StageKind::Terrain);
  graph.add(
      "terrain",
      [&](FrameGraph::Builder& b) {
        if (!terrain) return b.skip("the pack has no terrain program");
        if (b.written(shadowMaps)) b.read(shadowMaps);
        b.read(buffers);
        b.write(buffers);
      },
      [&] {
        PackGlProgram& p = *terrain->program;
        targets_->bindDraw(p.drawBuffers(), false, true);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_TRUE);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        applyBlend(terrain->state, nullptr);
        glUseProgram(p.id());
        p.setMatrices(world);
        bindSamplers(p, textures_->atlas.id());
        drawTerrain(*terrain, visible, MeshLayer::Opaque, DrawOrder::NearestFirst, &stats_);
        drawTerrain(*terrain, visible, MeshLayer::Cutout, DrawOrder::NearestFirst, &stats_);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
      });

  const auto addScreen = [&](Stage& s) {
    graph.add(
        s.slot,
        [&](FrameGraph::Builder& b) {
          if (b.written(shadowMaps)) b.read(shadowMaps);
          b.read(buffers);
          b.write(s.kind == StageKind::Final ? target : buffers);
        },
        [&] { screenPass(s); });
  };
  for (Stage& s : stages_)
    if (s.kind == StageKind::Deferred) addScreen(s);

  Stage* water = stageOf(StageKind::Water);
  graph.add(
      "water",
      [&](FrameGraph::Builder& b) {
        b.read(buffers);
        b.write(buffers);
      },
      [&] {
        targets_->keepOpaqueDepth();
        if (!water || quadsIn(visible, MeshLayer::Translucent) == 0) return;
        PackGlProgram& p = *water->program;
        targets_->bindDraw(p.drawBuffers(), false, true);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE);
        applyBlend(water->state, &kTranslucentBlend);
        glUseProgram(p.id());
        p.setMatrices(world);
        bindSamplers(p, textures_->atlas.id());
        drawTerrain(*water, visible, MeshLayer::Translucent, DrawOrder::FarthestFirst, &stats_);
        glDisable(GL_BLEND);
      });
  for (Stage& s : stages_)
    if (s.kind == StageKind::Composite) addScreen(s);
  if (Stage* final = stageOf(StageKind::Final)) {
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
  // The picture is opaque, as a window shows it, whatever alpha the pack left (mipmapped cutout edges).
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (const FrameGraph::Skipped& s : graph.skipped()) stats_.passesSkipped.push_back({s.pass, s.why});
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  for (int unit = 0; unit < 24; ++unit) glBindSampler(unitOf(unit), 0);
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

std::optional<GBufferPixels> PackRenderer::readReport() const {
  if (!targets_ || !reportShadow_ || !reportNormal_) return std::nullopt;
  const glm::ivec2 size = targets_->size();
  const auto count = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  GBufferPixels out;
  out.size = size;
  out.depth.resize(count);
  glGetTextureImage(targets_->depth(1), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(count * sizeof(float)), out.depth.data());
  std::vector<glm::vec4> shadow(count), normal(count);
  glGetTextureImage(targets_->main(*reportShadow_), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(count * sizeof(glm::vec4)), shadow.data());
  glGetTextureImage(targets_->main(*reportNormal_), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(count * sizeof(glm::vec4)), normal.data());
  const glm::mat3 toWorld = glm::inverse(glm::mat3(lastModelView_));
  out.normals.resize(count);
  out.scene.resize(count);
  // The pack's light levels are its own: no sky light to count cave leaks by.
  out.light.assign(count, glm::u8vec4(0, 255, 0, 0));
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 view = glm::vec3(normal[i]) * 2.0f - 1.0f;
    const float length = glm::length(view);
    const glm::dvec3 world =
        length > 1e-6f ? glm::dvec3(toWorld * (view / length)) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec2 oct = octEncode(world);
    out.normals[i] = glm::vec4(0.0f, 0.0f, static_cast<float>(oct.x), static_cast<float>(oct.y));
    out.scene[i] = glm::vec4(0.0f, 0.0f, 0.0f, shadow[i].r);
  }
  return out;
}

}  // namespace terrasol
