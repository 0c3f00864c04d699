#include "scene_render.h"

#include <chrono>
#include <iterator>

#include "core/error.h"
#include "core/paths.h"
#include "render/gl/render_target.h"
#include "scene/block_atlas.h"
#include "scene/scene_world.h"

namespace terrasol {
namespace {

std::string keyError(const SceneFile& scene, const std::string& key, const std::string& what) {
  std::string message = scene.file.string();
  message += ": ";
  message += key;
  message += ": ";
  message += what;
  return message;
}

PackStack openPacks(const SceneFile& scene) {
  PackStack packs;
  for (std::size_t i = 0; i < scene.packs.size(); ++i) {
    try {
      packs.push(ResourcePack::open(scene.packs[i]));
    } catch (const Error& e) {
      throw Error(keyError(scene, "packs[" + std::to_string(i) + "]", e.what()));
    }
  }
  return packs;
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DebugView debugViewOf(const SceneFile& scene) {
  for (std::size_t i = 0; i < std::size(kDebugViewNames); ++i) {
    if (scene.debugView == kDebugViewNames[i]) return static_cast<DebugView>(i);
  }
  throw Error(keyError(scene, "render.debug_view", "unknown view \"" + scene.debugView + "\""));
}

struct SceneRenderer::Gpu {
  Gpu(const ShaderPreprocessor& shaders, const Atlas& atlas, const BiomeTints& tints, const RendererOptions& options,
      glm::ivec2 size)
      : renderer(shaders, atlas, tints, options), target(size) {}
  DeferredRenderer renderer;
  SectionMeshes meshes;
  RenderTarget target;
};

SceneRenderer::SceneRenderer(const SceneFile& scene) : scene_(scene) {
  frame_.cameraPosition = scene.cameraPosition;
  frame_.cameraLookAt = scene.cameraLookAt;
  frame_.fovDegrees = scene.fov;
  frame_.ticks = scene.time;
  frame_.sunPathRotation = scene.sunPathRotation;
  frame_.viewDistance = static_cast<float>(scene.viewDistance * 16);
  frame_.debugView = debugViewOf(scene);
  frame_.materialAo = scene.materialAo;

  const auto start = std::chrono::steady_clock::now();
  const BlockRegistry blocks = BlockRegistry::fromFile(resourcePackDir() / "default" / "blocks.json");
  const PackStack packs = openPacks(scene);
  BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  const BiomeTints tints = loadTints(packs, atlas.problems);
  const BlockMeshTable table(blocks, [&](BlockId id, int face) { return atlas.textureOf(id, face); });
  stats_.loadMs = msSince(start);
  stats_.problems = atlas.problems;

  const auto worldStart = std::chrono::steady_clock::now();
  SceneWorld world(scene, blocks);
  const std::vector<SectionMesh> meshes = world.meshVisible(table);
  stats_.worldMs = msSince(worldStart);

  const ShaderPreprocessor shaders(shaderDir());
  RendererOptions options;
  options.ggxSpecular = scene.specular == "ggx";
  gpu_ = std::make_unique<Gpu>(shaders, atlas.atlas, tints, options, glm::ivec2(scene.width, scene.height));
  for (const auto& mesh : meshes) {
    gpu_->meshes.upload(mesh);
    stats_.quads += mesh.quads();
  }
  stats_.sections = meshes.size();
}

SceneRenderer::~SceneRenderer() = default;

DeferredRenderer& SceneRenderer::renderer() { return gpu_->renderer; }

Image SceneRenderer::render(std::vector<PassTiming>* timings) {
  const GLuint fbo = gpu_->target.framebuffer();
  gpu_->renderer.render(frame_, gpu_->meshes, fbo, gpu_->target.size());
  if (timings) gpu_->renderer.render(frame_, gpu_->meshes, fbo, gpu_->target.size(), timings);
  return gpu_->target.readPixels();
}

Image SceneRenderer::render(DebugView debugView) {
  const DebugView own = frame_.debugView;
  frame_.debugView = debugView;
  Image image = render();
  frame_.debugView = own;
  return image;
}

}  // namespace terrasol
