#include "game_renderer.h"

#include "core/error.h"
#include "core/log.h"
#include "core/paths.h"
#include "mesh/block_icon_mesh.h"
#include "scene/pack_blocks.h"

namespace terrasol {
namespace {

// Drawn at up to 64 pixels (the hotbar's largest slot); ImGui shrinks them smoothly.
constexpr int kIconPixels = 64;

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

std::unique_ptr<DeferredRenderer> makeRenderer(const BlockAssets& assets, const RendererOptions& options) {
  return std::make_unique<DeferredRenderer>(ShaderPreprocessor(shaderDir()), assets.atlas.atlas,
                                            assets.atlas.tints, assets.atlas.clouds, options);
}

// The settings that pick the renderer's variants.
RendererOptions optionsOf(const GameSettings& settings, const PropNeeds& props) {
  RendererOptions options;
  options.shadow = settings.shadow;
  options.reflections = settings.reflections;
  options.antialiasing = settings.antialiasing;
  options.bloom = settings.bloom;
  options.clouds = settings.clouds;
  options.fog = settings.fog;
  options.shafts = settings.shafts;
  options.props = props;
  return options;
}

}  // namespace

std::unique_ptr<BlockAssets> BlockAssets::load(const BlockRegistry& blocks,
                                               const std::vector<PackChoice>& packs,
                                               const BlockModelBake* defaultBake) {
  std::vector<std::string> names;
  const PackStack stack = openPacks(packs, names);
  return std::make_unique<BlockAssets>(blocks, stack, std::move(names), defaultBake);
}

BlockRegistry BlockAssets::registry(const std::vector<PackChoice>& packs) {
  BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  std::vector<std::string> names;
  std::vector<PackProblem> problems;
  try {
    blocks = withPackBlocks(std::move(blocks), openPacks(packs, names), problems);
  } catch (const Error&) {
    // A pack that cannot be read: the renderer reports it, and its blocks stay unknown.
  }
  for (const PackProblem& p : problems) logWarning(p.message);
  return blocks;
}

BlockAssets::BlockAssets(const BlockRegistry& blocks, const PackStack& stack, std::vector<std::string> names,
                         const BlockModelBake* defaultBake)
    : atlas(defaultBake && isDefaultPackAlone(stack) ? buildBlockAtlas(blocks, stack, *defaultBake)
                                                     : buildBlockAtlas(blocks, stack)),
      table(meshTableOf(blocks, atlas)),
      packNames(std::move(names)),
      packs(stack) {}

GameRenderer::GameRenderer(const BlockRegistry& blocks, const GameSettings& settings,
                           const BlockModelBake* defaultBake)
    : blocks_(blocks),
      assets_(BlockAssets::load(blocks, settings.packs, defaultBake)),
      options_(optionsOf(settings, {})),
      renderer_(makeRenderer(*assets_, options_)),
      iconStates_(terrasol::iconStates(blocks, assets_->atlas.placeholders)),
      iconOfBlock_(blocks.blockCount(), -1) {
  for (std::size_t i = 0; i < iconStates_.size(); ++i) {
    iconOfBlock_[blocks.blockIndex(iconStates_[i])] = static_cast<int>(i);
  }
  setShaderPack(settings.shaderpack);
}

std::unique_ptr<BlockAssets> GameRenderer::loadPacks(const std::vector<PackChoice>& packs) const {
  return BlockAssets::load(blocks_, packs);
}

void GameRenderer::commit(std::unique_ptr<BlockAssets> assets) {
  assets_ = std::move(assets);
  icons_.reset();  // drawn with the new packs when next shown
  renderer_ = makeRenderer(*assets_, options_);
  setShaderPack(shaderPackPath_);  // over the new atlas
  meshes_.clear();                 // their tiles index the old atlas; the remeshed sections come back
}

void GameRenderer::applySettings(const GameSettings& settings) {
  const RendererOptions options = optionsOf(settings, options_.props);
  if (options.shadow == options_.shadow && options.reflections == options_.reflections &&
      options.antialiasing == options_.antialiasing && options.bloom == options_.bloom) {
    return;
  }
  options_ = options;
  renderer_ = makeRenderer(*assets_, options_);
}

void GameRenderer::setPropNeeds(const PropNeeds& needs) {
  if (needs == options_.props) return;
  options_.props = needs;
  renderer_ = makeRenderer(*assets_, options_);
}

const BlockIcons& GameRenderer::icons() {
  if (!icons_) {
    std::vector<SectionMesh> meshes;
    for (const BlockId state : iconStates_) meshes.push_back(iconMesh(assets_->table, blocks_, state));
    icons_ = std::make_unique<BlockIcons>(ShaderPreprocessor(shaderDir()), assets_->atlas.atlas,
                                          assets_->atlas.tints, meshes, kIconPixels);
  }
  return *icons_;
}

std::optional<std::size_t> GameRenderer::iconOf(BlockId state) const {
  const int icon = iconOfBlock_[blocks_.blockIndex(state)];
  if (icon < 0) return std::nullopt;
  return static_cast<std::size_t>(icon);
}

void GameRenderer::setShaderPack(const std::filesystem::path& path) {
  shaderPackPath_ = path;
  pack_.reset();
  shaderPackError_.clear();
  if (path.empty()) return;
  try {
    pack_ = loadShaderPack(path, ShaderPreprocessor(shaderDir()), blocks_, assets_->table,
                           assets_->atlas.atlas, assets_->atlas.tints);
    logInfo("shader pack " + pack_->packName() + ": " + std::to_string(pack_->programNames().size()) +
            " programs");
  } catch (const Error& e) {
    shaderPackError_ = e.what();
    logError("shader pack not loaded, Terrasol's pipeline draws: " + shaderPackError_);
  }
}

void GameRenderer::render(const FrameInputs& frame, glm::ivec2 size, std::vector<PassTiming>* timings) {
  drawing().render(frame, meshes_, 0, size, timings);
}

}  // namespace terrasol
