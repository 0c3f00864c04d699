#pragma once
// The game's far terrain (settings "lod"): tiles from the world's generator round the player, built on
// a worker thread, the chunks the streamed world has meshed as the mask that hides them, and the
// player's edits: each edited column's summary replaces the generator's there, and its tiles are
// built again. A Minecraft save has no column rule: its tiles come from the chunks it holds, read whole.

#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "lod/lod_summary.h"
#include "lod/lod_terrain.h"
#include "play_world.h"
#include "render/lod_meshes.h"

namespace terrasol {

class FarTerrain {
 public:
  // Null when `settings` asks for none or the world's generator cannot be sampled.
  static std::unique_ptr<FarTerrain> create(const LodSettings& settings, const PlayWorld& world,
                                            LodPalette palette);

  // Before each frame: the player's new edits, the mask, and the set for a camera at `camera`.
  void update(glm::dvec3 camera, int viewDistance, const PlayWorld& world, LodMeshes& meshes);
  LodTerrainStats stats() const { return terrain_.stats(); }
  int distance() const { return settings_.distance; }

 private:
  FarTerrain(const LodSettings& settings, const PlayWorld& world, LodPalette palette);
  LodTile tile(LodTileKey key) const;  // worker threads

  const ChunkGenerator& generator_;
  const BlockRegistry& blocks_;
  LodSettings settings_;
  mutable std::mutex editsMutex_;
  std::map<std::pair<int, int>, LodColumn> edited_;  // columns the player changed, as they are now
  std::size_t editsSeen_ = 0;
  std::vector<std::uint8_t> mask_;
  glm::ivec2 maskOrigin_{0};
  LodTerrain terrain_;  // last: its workers read the above
};

}  // namespace terrasol
