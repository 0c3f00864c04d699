#include "game_renderer.h"

#include "core/error.h"
#include "core/paths.h"

namespace terrasol {
namespace {

PackStack openPacks(const std::vector<PackChoice>& packs, std::vector<std::string>& names) {
  PackStack stack;
  stack.push(ResourcePack::open(resourcePackDir() / "default"));
  names.push_back("default");
  for (const PackChoice& p : packs) {
    if (!p.enabled) continue;
    stack.push(ResourcePack::open(p.path));
    names.push_back(p.path.filename().string());
  }
  return stack;
}

std::unique_ptr<DeferredRenderer> makeRenderer(const BlockAssets& assets, const ShadowSettings& shadow,
                                               const ReflectionSettings& reflections,
                                               const PropNeeds& props) {
  RendererOptions options;
  options.shadow = shadow;
  options.reflections = reflections;
  options.props = props;
  return std::make_unique<DeferredRenderer>(ShaderPreprocessor(shaderDir()), assets.atlas.atlas, assets.colormaps, options);
}

}  // namespace

std::unique_ptr<BlockAssets> BlockAssets::load(const BlockRegistry& blocks, const std::vector<PackChoice>& packs) {
  std::vector<std::string> names;
  const PackStack stack = openPacks(packs, names);
  return std::make_unique<BlockAssets>(blocks, stack, std::move(names));
}

BlockAssets::BlockAssets(const BlockRegistry& blocks, const PackStack& stack, std::vector<std::string> names)
    : atlas(buildBlockAtlas(blocks, stack)),
      colormaps(loadColormaps(stack, atlas.problems)),
      table(meshTableOf(blocks, atlas)),
      packNames(std::move(names)) {}

GameRenderer::GameRenderer(const BlockRegistry& blocks, const GameSettings& settings)
    : blocks_(blocks),
      assets_(BlockAssets::load(blocks, settings.packs)),
      renderer_(makeRenderer(*assets_, settings.shadow, settings.reflections, {})),
      shadow_(settings.shadow),
      reflections_(settings.reflections) {}

std::unique_ptr<BlockAssets> GameRenderer::loadPacks(const std::vector<PackChoice>& packs) const {
  return BlockAssets::load(blocks_, packs);
}

void GameRenderer::commit(std::unique_ptr<BlockAssets> assets) {
  assets_ = std::move(assets);
  icons_.reset();
  renderer_ = makeRenderer(*assets_, shadow_, reflections_, propNeeds_);
  meshes_.clear();  // their tiles index the old atlas; the remeshed sections come back
}

void GameRenderer::applySettings(const GameSettings& settings) {
  if (settings.shadow == shadow_ && settings.reflections == reflections_) return;
  shadow_ = settings.shadow;
  reflections_ = settings.reflections;
  icons_.reset();
  renderer_ = makeRenderer(*assets_, shadow_, reflections_, propNeeds_);
}

void GameRenderer::setPropNeeds(const PropNeeds& needs) {
  if (needs == propNeeds_) return;
  propNeeds_ = needs;
  icons_.reset();
  renderer_ = makeRenderer(*assets_, shadow_, reflections_, propNeeds_);
}

GLuint GameRenderer::iconTexture() {
  if (!icons_) {
    icons_ = gl::TextureView::create(GL_TEXTURE_2D, renderer_->atlasAlbedo(), GL_RGBA8, 0, 1, 0, 1);
    glTextureParameteri(icons_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(icons_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  return icons_.id();
}

void GameRenderer::render(const FrameInputs& frame, glm::ivec2 size, std::vector<PassTiming>* timings) {
  renderer_->render(frame, meshes_, 0, size, timings);
}

}  // namespace terrasol
