#pragma once
// Far terrain round a moving camera: the tiles selectLodTiles picks, sampled from a source and meshed
// on worker threads, and handed on a whole set at a time. A set is handed on only once every tile in
// it is ready, so levels never overlap or leave a gap while the camera moves; until then the last set
// stays. Edits drop the tiles over them, and the next set brings them back from the source.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <tuple>
#include <vector>

#include "lod/lod_mesh.h"
#include "lod/lod_select.h"

namespace terrasol {

// A tile's cells from wherever they come from (the generator, chunks); called on worker threads.
using LodTileSource = std::function<LodTile(LodTileKey)>;

struct LodSet {
  std::vector<std::shared_ptr<const LodMesh>> meshes;  // nearest first
  std::uint64_t generation = 0;
};

struct LodTerrainStats {
  int tiles = 0, levels = 0;    // in the set shown
  std::size_t meshBytes = 0;    // of its vertices
  std::size_t cachedBytes = 0;  // tiles and meshes held (the set shown and the one being built)
  int pending = 0;              // tiles still to build for the next set
};

class LodTerrain {
 public:
  // `threads` 0: everything is built on the calling thread, in update().
  LodTerrain(LodTileSource source, LodPalette palette, LodLevels levels, int threads);
  ~LodTerrain();
  LodTerrain(const LodTerrain&) = delete;
  LodTerrain& operator=(const LodTerrain&) = delete;

  // The camera this frame: starts what the set for it needs. With `wait`, returns once it is ready.
  void update(const LodView& view, bool wait = false);
  // A new set to show, once one is complete (each set once).
  std::optional<LodSet> takeSet();
  // The column (x, z) changed: the tiles over it come from the source again.
  void invalidate(int x, int z);

  LodTerrainStats stats() const;
  const LodLevels& levels() const { return levels_; }

 private:
  using MeshKey = std::tuple<int, int, int, bool>;  // level, x, z, all walls
  static MeshKey meshKey(const LodSelected& s) {
    return {s.key.level, s.key.x, s.key.z, s.touchesFullDetail};
  }
  void work(std::stop_token stop);
  void build(const LodSelected& s);  // without the lock
  void startMissing();               // with it
  void finishIfReady();              // with it

  LodTileSource source_;
  LodPalette palette_;
  LodLevels levels_;

  mutable std::mutex mutex_;
  std::condition_variable_any wake_, done_;
  std::deque<LodSelected> queue_;
  std::set<MeshKey> building_;
  std::map<std::tuple<int, int, int>, std::shared_ptr<const LodTile>> tiles_;
  std::map<MeshKey, std::shared_ptr<const LodMesh>> meshes_;
  std::vector<LodSelected> wanted_;  // the set being built
  bool wantedChanged_ = false;
  std::optional<LodSet> ready_;
  std::vector<LodSelected> shown_;
  std::uint64_t generation_ = 0;
  std::uint64_t edits_ = 0;  // invalidations so far: a tile built across one is built again
  std::vector<std::jthread> workers_;
};

}  // namespace terrasol
