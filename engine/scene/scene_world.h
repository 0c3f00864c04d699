#pragma once
// A scene's world, ready to draw: the chunks around every frame's camera generated, the scene's edits
// applied, light fully propagated, and every visible section meshed. A camera path may visit places
// far apart (one biome a frame): only the areas round its frames' cameras are made. Main thread only.

#include <memory>
#include <vector>

#include "light/light_engine.h"
#include "mesh/mesher.h"
#include "scene/scene_file.h"
#include "world/generator.h"

namespace terrasol {

class SceneWorld {
 public:
  // Generates chunks within view distance + 1 of each frame's camera (the extra ring gives the
  // visible ones their light and mesh halo), applies the edits, then lights everything. Throws Error
  // naming the scene key for an unknown block or generator.
  SceneWorld(const SceneFile& scene, const BlockRegistry& blocks);
  // With the blocks' shapes made already (from the default pack: blockShapesOf).
  SceneWorld(const SceneFile& scene, const BlockRegistry& blocks, BlockShapes shapes);

  // Meshes of every section that has faces, within the view distance of a frame's camera, and the empty
  // meshes of closed sections (their face links hide what is behind them).
  std::vector<SectionMesh> meshVisible(const BlockMeshTable& table) const;

  // Applies the edits keyed to frames up to `frame` not applied yet, block by block through the light
  // engine as the game does, and remeshes only the sections whose blocks or light changed. Returns
  // their new meshes (within the view distance; an empty one means the section's mesh goes).
  std::vector<SectionMesh> advanceTo(int frame, const BlockMeshTable& table);

  // The chunks drawn in full detail: within the view distance of a frame's camera.
  bool shown(ChunkPos chunk) const { return withinView(SectionPos{chunk.x, 0, chunk.z}); }
  const ChunkGenerator& generator() const { return *generator_; }
  int viewDistance() const { return viewDistance_; }

  World& world() { return world_; }
  const World& world() const { return world_; }
  LightEngine& light() { return light_; }
  const LightEngine& light() const { return light_; }

 private:
  struct Edit {
    SceneEdit edit;
    BlockId block;
    bool applied;
  };
  // Calls `f(pos)` for each cell of the edit inside the loaded chunks and the world's height.
  template <class F>
  void forEachCell(const SceneEdit& edit, F&& f) const;
  bool withinView(SectionPos pos) const;

  BlockShapes shapes_;  // the default pack's, as the game's
  World world_;
  LightEngine light_;
  std::unique_ptr<ChunkGenerator> generator_;
  std::vector<ChunkPos> centres_;  // each frame's camera chunk, each once
  int viewDistance_;
  std::vector<ChunkPos> loaded_;  // within view distance + 1 of a centre
  std::vector<Edit> edits_;       // in file order
};

}  // namespace terrasol
