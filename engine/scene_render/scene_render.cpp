#include "scene_render/scene_render.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <optional>

#include "core/error.h"
#include "core/paths.h"
#include "core/temporal_jitter.h"
#include "pack_render/pack_renderer.h"
#include "render/gl/render_target.h"
#include "scene/block_atlas.h"
#include "scene/block_colours.h"
#include "scene/camera_path.h"
#include "scene/pack_blocks.h"
#include "scene/scene_world.h"
#include "scene_render/eye_light.h"
#include "scene_render/placed_props.h"
#include "scene_render/scene_lod.h"
#include "scene_render/under_water.h"

namespace terrasol {
namespace {

PackStack openPacks(const SceneFile& scene) {
  PackStack packs;
  for (std::size_t i = 0; i < scene.packs.size(); ++i) {
    try {
      packs.push(ResourcePack::open(scene.packs[i]));
    } catch (const Error& e) {
      throw Error(sceneError(scene, "packs[" + std::to_string(i) + "]", e.what()));
    }
  }
  return packs;
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

// The CPU side: blocks, atlas, the mesher's table and the world, kept for edits keyed to frames.
struct SceneRenderer::World {
  World(const SceneFile& scene, const PackStack& packs)
      : blocks(withPackBlocks(BlockRegistry::load(resourcePackDir() / "default" / "blocks.json"), packs,
                              packBlockProblems)),
        bake(bakeBlockModels(blocks, packs)),
        atlas(buildBlockAtlas(blocks, packs, *bake)),
        table(meshTableOf(blocks, atlas)),
        // Shapes are the default pack's: from this bake where that is all there is.
        world(scene, blocks,
              isDefaultPackAlone(packs) ? blockShapesOf(blocks, *bake) : defaultPackShapes(blocks)),
        lod(SceneLod::create(scene.lod, world, lodPaletteOf(blocks, atlas))) {
    bake.reset();
    atlas.problems.insert(atlas.problems.end(), packBlockProblems.begin(), packBlockProblems.end());
  }
  std::vector<PackProblem> packBlockProblems;  // blocks.json's blocks' own come with the atlas
  BlockRegistry blocks;
  std::optional<BlockModelBake> bake;  // only while the rest is made
  BlockAtlas atlas;
  BlockMeshTable table;
  SceneWorld world;
  std::unique_ptr<SceneLod> lod;  // render.lod, when the generator can be sampled
};

namespace {

// The scene's props, each lit from the world; a model that cannot be loaded names its scene key.
PlacedProps placeProps(const SceneFile& scene, const SceneWorld& world) {
  PlacedProps props;
  for (const SceneProp& prop : scene.props) {
    try {
      props.place(prop.model, propTransform(prop), world.world(), world.light());
    } catch (const Error& e) {
      throw Error(sceneError(scene, prop.key + ".model", e.what()));
    }
  }
  return props;
}

RendererOptions withProps(RendererOptions options, const PlacedProps& props) {
  options.props = props.gpu().needs();
  return options;
}

}  // namespace

struct SceneRenderer::Gpu {
  Gpu(const ShaderPreprocessor& shaders, const BlockAtlas& atlas, const RendererOptions& options,
      glm::ivec2 size, const SceneFile& scene, const SceneWorld& world)
      : props(placeProps(scene, world)),
        renderer(shaders, atlas.atlas, atlas.tints, atlas.clouds, withProps(options, props)),
        target(size) {}
  PlacedProps props;  // before the renderer, which is built for what they need
  DeferredRenderer renderer;
  std::unique_ptr<PackRenderer> pack;  // render.shaderpack: drawn in the renderer's place
  SectionMeshes meshes;
  LodMeshes lod;
  RenderTarget target;
};

SceneRenderer::SceneRenderer(const SceneFile& scene)
    : scene_(scene), debugView_(scene.debugView), resolution_(scene.renderScale) {
  const auto start = std::chrono::steady_clock::now();
  const PackStack packs = openPacks(scene);
  world_ = std::make_unique<World>(scene, packs);
  stats_.problems = world_->atlas.problems;
  const std::vector<SectionMesh> meshes = world_->world.meshVisible(world_->table);
  stats_.loadMs = msSince(start);

  const ShaderPreprocessor shaders(shaderDir());
  RendererOptions options;
  options.ggxSpecular = scene.specular == SpecularModel::Ggx;
  options.shadow = scene.shadow;
  options.caveCulling = scene.caveCulling;
  options.shadowCasterCulling = scene.shadowCasterCulling;
  options.leaveOutAbsentMaps = scene.leaveOutAbsentMaps;
  options.cullFacesAway = scene.cullFacesAway;
  options.cullPasses = scene.cullPasses;
  options.reflections = scene.reflections;
  options.water = scene.water;
  options.antialiasing = scene.antialiasing;
  options.bloom = scene.bloom;
  options.clouds = scene.clouds;
  options.fog = scene.fog;
  options.shafts = scene.shafts;
  gpu_ = std::make_unique<Gpu>(shaders, world_->atlas, options, glm::ivec2(scene.width, scene.height), scene,
                               world_->world);
  if (!scene.shaderpack.empty()) {
    // A pack that cannot be read or built leaves Terrasol's pipeline drawing, with the pack's error.
    try {
      gpu_->pack = loadShaderPack(scene.shaderpack, shaders, world_->blocks, world_->table,
                                  world_->atlas.atlas, world_->atlas.tints, scene.shadowCasterCulling);
    } catch (const Error& e) {
      stats_.shaderpackError = e.what();
    }
  }
  for (const auto& mesh : meshes) {
    gpu_->meshes.upload(mesh);
    stats_.quads += mesh.quads();
    stats_.sections += mesh.empty() ? 0 : 1;
  }
}

SceneRenderer::~SceneRenderer() = default;

SceneFile lodTruthScene(const SceneFile& scene) {
  SceneFile truth = scene;
  truth.viewDistance = std::max(scene.viewDistance, scene.lod.distance);
  truth.lod.distance = 0;
  return truth;
}

DeferredRenderer& SceneRenderer::renderer() {
  return gpu_->renderer;
}

std::optional<SceneLodStats> SceneRenderer::lodStats() const {
  if (!world_->lod) return std::nullopt;
  const LodTerrainStats t = world_->lod->stats();
  SceneLodStats s{t.tiles, t.levels, 0, t.cachedBytes, gpu_->lod.gpuBytes(), world_->lod->longestUpdateMs()};
  for (const LodMeshes::Tile& tile : gpu_->lod.tiles())
    s.triangles += static_cast<std::size_t>(2 * tile.quads + tile.triangles);
  return s;
}

const PackRenderer* SceneRenderer::shaderPack() const {
  return gpu_->pack.get();
}

WorldRenderer& SceneRenderer::drawing() {
  if (gpu_->pack) return *gpu_->pack;
  return gpu_->renderer;
}

const terrasol::World& SceneRenderer::world() const {
  return world_->world.world();
}

FrameInputs SceneRenderer::inputsFor(int frame) const {
  const CameraState camera = cameraAtFrame(scene_, frame);
  FrameInputs inputs;
  inputs.cameraPosition = camera.position;
  inputs.cameraLookAt = camera.position + camera.forward;
  inputs.cameraUp = camera.up;
  inputs.fovDegrees = camera.fov;
  inputs.ticks = camera.time;
  inputs.sunPathRotation = scene_.sunPathRotation;
  inputs.viewDistance = static_cast<float>(scene_.viewDistance * kChunkSize);  // chunks to blocks
  if (world_->lod) {
    inputs.lod = &gpu_->lod;
    inputs.lodShadows = scene_.lod.shadows;
    inputs.viewDistance = static_cast<float>(std::max(scene_.viewDistance, scene_.lod.distance) * kChunkSize);
  }
  inputs.renderScale = scene_.renderScale;  // with render.target_fps, the most renderFrame uses
  inputs.debugView = debugView_;
  inputs.materialAo = scene_.materialAo;
  inputs.props = &gpu_->props.gpu();
  inputs.underWater = underWaterAt(world_->world.world(), world_->world.light(), camera.position);
  inputs.eyeLight = eyeLightAt(world_->world.light(), camera.position);
  return inputs;
}

void SceneRenderer::advanceTo(int frame) {
  const std::vector<SectionMesh> changed = world_->world.advanceTo(frame, world_->table);
  for (const SectionMesh& mesh : changed) gpu_->meshes.upload(mesh);
  if (!changed.empty()) gpu_->props.relightAll(world_->world.world(), world_->world.light());
  if (world_->lod) world_->lod->update(cameraAtFrame(scene_, frame).position, gpu_->lod);
}

RenderedFrame SceneRenderer::renderFrame(int frame, const FrameRequest& request) {
  advanceTo(frame);
  FrameInputs inputs = inputsFor(frame);
  if (request.debugView) inputs.debugView = *request.debugView;
  inputs.shadowCentreOffset = request.shadowCentreOffset;
  inputs.reuseShadowMap = request.reuseShadowMap;
  inputs.aside = request.aside;
  inputs.crack = request.crack;
  RenderedFrame out;
  const GLuint fbo = gpu_->target.framebuffer();
  if (scene_.targetFps > 0) inputs.renderScale = resolution_.scale();
  if (request.renderScale) inputs.renderScale = *request.renderScale;
  if (frame == 0 && !request.aside) warmHistory(inputs);
  const auto start = std::chrono::steady_clock::now();
  drawing().render(inputs, gpu_->meshes, fbo, gpu_->target.size(), request.timed ? &out.timings : nullptr);
  if (scene_.targetFps > 0) {
    glFinish();  // the frame's whole time, as the game measures it
    resolution_.update(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
        scene_.targetFps);
  }
  out.image = gpu_->target.readPixels();
  out.stats = drawing().lastFrame();
  out.geometry = drawing().lastGeometry();
  if (gpu_->pack) {
    // The pack's float buffers for NaN; its G-buffer, when it names one, for the shadow report.
    if (request.checkNan) out.nanPixels = gpu_->pack->nonFinitePixels();
    if (request.readBack) {
      if (auto pixels = gpu_->pack->readReport()) out.pixels = std::move(*pixels);
    }
    return out;
  }
  if (request.checkNan || request.readBack) {
    out.pixels = gpu_->renderer.gbuffer()->read();
    out.nanPixels = nonFinitePixels(out.pixels) + gpu_->renderer.nonFiniteResolved();
  }
  if (request.readBack) out.reflections = gpu_->renderer.readReflections();
  return out;
}

void SceneRenderer::warmHistory(const FrameInputs& inputs) {
  drawing().forgetHistory();
  if (scene_.antialiasing != Antialiasing::Taa || inputs.debugView != DebugView::None || gpu_->pack) return;
  const int frames = std::min(jitterPhases(inputs.renderScale), kTaaWarmFrames);
  for (int i = 1; i < frames; ++i)
    drawing().render(inputs, gpu_->meshes, gpu_->target.framebuffer(), gpu_->target.size());
}

void SceneRenderer::draw(int frame, GLuint framebuffer, glm::ivec2 size) {
  advanceTo(frame);
  drawing().render(inputsFor(frame), gpu_->meshes, framebuffer, size);
}

Image SceneRenderer::render(std::vector<PassTiming>* timings) {
  RenderedFrame frame = renderFrame(0);
  if (!timings) return std::move(frame.image);
  FrameRequest timed;
  timed.timed = true;
  frame = renderFrame(0, timed);
  *timings = std::move(frame.timings);
  return std::move(frame.image);
}

Image SceneRenderer::render(DebugView debugView) {
  FrameRequest request;
  request.debugView = debugView;
  return renderFrame(0, request).image;
}

}  // namespace terrasol
