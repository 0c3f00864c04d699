#pragma once
// A scene's world, ready to draw: the chunks around the camera generated, the scene's edits applied,
// light fully propagated, and every visible section meshed. Main thread only.

#include <memory>
#include <vector>

#include "light/light_engine.h"
#include "mesh/mesher.h"
#include "scene/scene_file.h"
#include "world/generator.h"

namespace terrasol {

class SceneWorld {
 public:
  // Generates chunks within view distance + 1 of the camera (the extra ring gives the visible ones
  // their light and mesh halo), applies the edits, then lights everything. Throws Error naming the
  // scene key for an unknown block or generator.
  SceneWorld(const SceneFile& scene, const BlockRegistry& blocks);

  // Meshes of every section that has faces, within the view distance of the camera.
  std::vector<SectionMesh> meshVisible(const BlockMeshTable& table) const;

  World& world() { return world_; }
  LightEngine& light() { return light_; }
  ChunkPos centre() const { return centre_; }
  int viewDistance() const { return viewDistance_; }

 private:
  void applyEdit(const SceneEdit& edit, BlockId block, int loadRadius);

  World world_;
  LightEngine light_;
  std::unique_ptr<ChunkGenerator> generator_;
  ChunkPos centre_;
  int viewDistance_;
};

}  // namespace terrasol
