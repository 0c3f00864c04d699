#pragma once
// What the game draws with: the packs' atlas and the mesher's table built from it, the deferred
// renderer (rebuilt when settings that pick its shader variants change) and the section meshes on
// the GPU. Packs reload without a restart: new assets, then every section is meshed again. A shader
// pack, when one is chosen, draws in the deferred renderer's place; one that fails leaves it drawing.

#include <memory>
#include <optional>
#include <vector>

#include "mesh/mesher.h"
#include "pack_render/pack_renderer.h"
#include "render/block_icons.h"
#include "render/deferred_renderer.h"
#include "render/lod_meshes.h"
#include "scene/block_atlas.h"
#include "settings.h"

namespace terrasol {

// CPU side of the packs: immutable once built, so mesher threads may read the table.
struct BlockAssets {
  // The default pack with the enabled `packs` over it. Throws Error naming a pack that cannot be read.
  // `defaultBake`, the default pack's models baked already, is used where no pack is enabled.
  static std::unique_ptr<BlockAssets> load(const BlockRegistry& blocks, const std::vector<PackChoice>& packs,
                                           const BlockModelBake* defaultBake = nullptr);
  BlockAssets(const BlockRegistry& blocks, const PackStack& stack, std::vector<std::string> names,
              const BlockModelBake* defaultBake = nullptr);
  // Minecraft's table and the default blocks.json, with the blocks the enabled `packs` add: fixed for
  // the game's run, so a pack enabled later draws its own blocks from the next start.
  static BlockRegistry registry(const std::vector<PackChoice>& packs);
  BlockAtlas atlas;
  BlockMeshTable table;
  std::vector<std::string> packNames;  // bottom to top, as loaded
  PackStack packs;                     // for what else the packs hold (sounds)
};

class GameRenderer {
 public:
  // `defaultBake`: as BlockAssets::load's, for the first assets.
  GameRenderer(const BlockRegistry& blocks, const GameSettings& settings,
               const BlockModelBake* defaultBake = nullptr);

  const BlockRegistry& blocks() const { return blocks_; }
  const BlockAssets& assets() const { return *assets_; }
  // Builds the new packs' assets; the caller remeshes with the new table, then commit() swaps them in
  // (the old table lives until the old mesher threads are gone). Throws Error for a bad pack.
  std::unique_ptr<BlockAssets> loadPacks(const std::vector<PackChoice>& packs) const;
  void commit(std::unique_ptr<BlockAssets> assets);
  // New shader variants and targets for changed shadow or reflection settings.
  void applySettings(const GameSettings& settings);
  // The props' needs (render/props.h): new prop variants when they change.
  void setPropNeeds(const PropNeeds& needs);
  // Draws with the shader pack at `path` from the next frame (empty: Terrasol's pipeline). One that
  // cannot be read or built leaves Terrasol's pipeline drawing; its error is kept for the menu.
  void setShaderPack(const std::filesystem::path& path);
  const std::string& shaderPackError() const { return shaderPackError_; }
  // The pack drawing now, or null.
  const PackRenderer* shaderPack() const { return pack_.get(); }

  void upload(const SectionMesh& mesh) { meshes_.upload(mesh); }
  // Far terrain's tiles on the GPU and the chunks full detail covers.
  LodMeshes& lod() { return lod_; }
  const LodMeshes& lod() const { return lod_; }
  void render(const FrameInputs& frame, glm::ivec2 size, std::vector<PassTiming>* timings);
  const FrameStats& lastFrame() const { return drawing().lastFrame(); }
  std::size_t sectionsOnGpu() const { return meshes_.sections().size(); }
  // The inventory's icons (drawn on first use, again after the packs change), one per block of
  // iconStates(); iconOf gives a state's block's icon, if its block has one.
  const BlockIcons& icons();
  const std::vector<BlockId>& iconStates() const { return iconStates_; }
  std::optional<std::size_t> iconOf(BlockId state) const;

 private:
  // The shader pack when one is drawing, else the deferred renderer.
  WorldRenderer& drawing() const {
    if (pack_) return *pack_;
    return *renderer_;
  }

  const BlockRegistry& blocks_;
  std::unique_ptr<BlockAssets> assets_;
  RendererOptions options_;  // before the renderer, which is built with them
  std::unique_ptr<DeferredRenderer> renderer_;
  std::filesystem::path shaderPackPath_;
  std::unique_ptr<PackRenderer> pack_;
  std::string shaderPackError_;

  SectionMeshes meshes_;
  LodMeshes lod_;
  std::vector<BlockId> iconStates_;
  std::vector<int> iconOfBlock_;  // per block type: its icon, or -1
  std::unique_ptr<BlockIcons> icons_;
};

}  // namespace terrasol
