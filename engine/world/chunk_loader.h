#pragma once
// Loads chunks on a pool of worker threads: from the save when the chunk was saved, otherwise from
// the generator. The main thread only queues requests and collects finished chunks; it never waits
// for a chunk to be generated.

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "world/chunk.h"
#include "world/generator.h"
#include "world/world_storage.h"

namespace terrasol {

class ChunkLoader {
 public:
  // `storage` may be null (nothing is ever saved). `threads` >= 1.
  ChunkLoader(const ChunkGenerator& generator, WorldStorage* storage, int threads);
  ~ChunkLoader();  // stops the workers; queued requests are dropped
  ChunkLoader(const ChunkLoader&) = delete;
  ChunkLoader& operator=(const ChunkLoader&) = delete;

  // Queued requests closest to this chunk are served first.
  void setCenter(ChunkPos center);
  void request(ChunkPos pos);
  // Drops queued requests (not ones being worked on) for which `drop` is true.
  void cancelIf(const std::function<bool(ChunkPos)>& drop);
  // Chunks finished since the last call, in completion order.
  std::vector<std::unique_ptr<Chunk>> takeFinished();
  // Chunks that could not be loaded (their region is unreadable) since the last call; ask again later.
  std::vector<ChunkPos> takeFailed();
  // Requests not handed back yet: queued, in progress, or finished (or failed) and not taken.
  std::size_t pending() const;

 private:
  void work();

  const ChunkGenerator& generator_;
  WorldStorage* storage_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<ChunkPos> queue_;
  std::vector<std::unique_ptr<Chunk>> finished_;
  std::vector<ChunkPos> failed_;
  ChunkPos center_;
  std::size_t inProgress_ = 0;
  bool stop_ = false;
  std::vector<std::jthread> workers_;
};

}  // namespace terrasol
