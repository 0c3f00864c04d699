#pragma once
// Keeps the chunks around a centre loaded: requests missing ones from a ChunkLoader, adds finished
// ones to the World, and saves (when edited) and unloads those that fall out of range, so memory
// stays bounded however far the player travels. Main thread only.

#include <functional>
#include <unordered_set>
#include <vector>

#include "world/chunk_loader.h"
#include "world/world.h"

namespace terrasol {

class ChunkStreamer {
 public:
  // Chunks within `radius` (in chunks, a square) of the centre are loaded; those beyond radius + 1
  // are unloaded (the margin keeps a player walking along a border from reloading chunks).
  ChunkStreamer(World& world, const ChunkGenerator& generator, WorldStorage* storage, int threads,
                int radius);

  // Called right after a chunk is added to the World, and right before one is removed (e.g. the
  // light engine's chunkLoaded / chunkUnloading, the mesher's dirty marks).
  void setHooks(std::function<void(ChunkPos)> loaded, std::function<void(ChunkPos)> unloading) {
    loaded_ = std::move(loaded);
    unloading_ = std::move(unloading);
  }

  // Call once a frame. Never blocks on generation. Returns the chunks added to the world, closest to
  // the centre first, while `more()` says yes (each added chunk is lit by the hook: a frame's budget
  // for that work); finished chunks left over wait for the next call. An edited chunk whose save
  // fails stays loaded (the error is logged) and is tried again next time.
  std::vector<ChunkPos> update(ChunkPos center, const std::function<bool()>& more = {});
  // Saves every edited chunk (e.g. before quitting).
  void saveAll();

  int radius() const { return radius_; }
  // Requested chunks not in the world yet (being loaded, or finished and waiting to be added).
  std::size_t pending() const { return loader_.pending() + ready_.size(); }
  void setRadius(int radius) { radius_ = radius; }

 private:
  World& world_;
  WorldStorage* storage_;
  std::function<void(ChunkPos)> loaded_, unloading_;
  int radius_;
  std::unordered_set<ChunkPos> requested_;
  std::vector<std::unique_ptr<Chunk>> ready_;  // finished, not added yet
  ChunkLoader loader_;                         // last: its workers stop before the rest is destroyed
};

}  // namespace terrasol
