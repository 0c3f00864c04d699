#pragma once
// What the game draws with: the packs' atlas and the mesher's table built from it, the deferred
// renderer (rebuilt when settings that pick its shader variants change) and the section meshes on
// the GPU. Packs reload without a restart: new assets, then every section is meshed again.

#include <memory>
#include <vector>

#include "mesh/mesher.h"
#include "render/deferred_renderer.h"
#include "scene/block_atlas.h"
#include "settings.h"

namespace terrasol {

// CPU side of the packs: immutable once built, so mesher threads may read the table.
struct BlockAssets {
  // The default pack with the enabled `packs` over it. Throws Error naming a pack that cannot be read.
  static std::unique_ptr<BlockAssets> load(const BlockRegistry& blocks, const std::vector<PackChoice>& packs);
  BlockAssets(const BlockRegistry& blocks, const PackStack& stack, std::vector<std::string> names);
  BlockAtlas atlas;
  BiomeColormaps colormaps;
  BlockMeshTable table;
  std::vector<std::string> packNames;  // bottom to top, as loaded
};

class GameRenderer {
 public:
  GameRenderer(const BlockRegistry& blocks, const GameSettings& settings);

  const BlockAssets& assets() const { return *assets_; }
  // Builds the new packs' assets; the caller remeshes with the new table, then commit() swaps them in
  // (the old table lives until the old mesher threads are gone). Throws Error for a bad pack.
  std::unique_ptr<BlockAssets> loadPacks(const std::vector<PackChoice>& packs) const;
  void commit(std::unique_ptr<BlockAssets> assets);
  // New shader variants and targets for changed shadow or reflection settings.
  void applySettings(const GameSettings& settings);
  // The props' needs (render/props.h): new prop variants when they change.
  void setPropNeeds(const PropNeeds& needs);

  void upload(const SectionMesh& mesh) { meshes_.upload(mesh); }
  void render(const FrameInputs& frame, glm::ivec2 size, std::vector<PassTiming>* timings);
  const FrameStats& lastFrame() const { return renderer_->lastFrame(); }
  std::size_t sectionsOnGpu() const { return meshes_.sections().size(); }
  // The atlas's level 0 as plain RGBA8 (the HUD draws into a non-sRGB target: the stored sRGB bytes
  // are what should reach the screen).
  GLuint iconTexture();

 private:
  const BlockRegistry& blocks_;
  std::unique_ptr<BlockAssets> assets_;
  std::unique_ptr<DeferredRenderer> renderer_;
  ShadowSettings shadow_;
  ReflectionSettings reflections_;
  PropNeeds propNeeds_;
  SectionMeshes meshes_;
  gl::TextureView icons_;  // of renderer_'s atlas; remade with it
};

}  // namespace terrasol
