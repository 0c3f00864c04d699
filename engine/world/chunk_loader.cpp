#include "world/chunk_loader.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/log.h"
#include "core/thread_priority.h"

namespace terrasol {
namespace {

std::int64_t distance2(ChunkPos a, ChunkPos b) {
  const std::int64_t dx = a.x - b.x, dz = a.z - b.z;
  return dx * dx + dz * dz;
}

}  // namespace

ChunkLoader::ChunkLoader(const ChunkGenerator& generator, WorldStorage* storage, int threads)
    : generator_(generator), storage_(storage) {
  for (int i = 0; i < std::max(threads, 1); ++i)
    workers_.emplace_back([this] {
      lowerThisThreadsPriority();
      work();
    });
}

ChunkLoader::~ChunkLoader() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  workers_.clear();  // joins
}

void ChunkLoader::setCenter(ChunkPos center) {
  std::lock_guard lock(mutex_);
  center_ = center;
}

void ChunkLoader::request(ChunkPos pos) {
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(pos);
  }
  wake_.notify_one();
}

void ChunkLoader::cancelIf(const std::function<bool(ChunkPos)>& drop) {
  std::lock_guard lock(mutex_);
  std::erase_if(queue_, drop);
}

std::vector<std::unique_ptr<Chunk>> ChunkLoader::takeFinished() {
  std::lock_guard lock(mutex_);
  return std::exchange(finished_, {});
}

std::vector<ChunkPos> ChunkLoader::takeFailed() {
  std::lock_guard lock(mutex_);
  return std::exchange(failed_, {});
}

std::size_t ChunkLoader::pending() const {
  std::lock_guard lock(mutex_);
  return queue_.size() + inProgress_ + finished_.size() + failed_.size();
}

void ChunkLoader::work() {
  for (;;) {
    ChunkPos pos;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
      if (stop_) return;
      // Nearest first; the queue holds at most a few thousand entries, so a scan is cheap.
      const auto nearest = std::min_element(queue_.begin(), queue_.end(), [this](ChunkPos a, ChunkPos b) {
        return distance2(a, center_) < distance2(b, center_);
      });
      pos = *nearest;
      *nearest = queue_.back();
      queue_.pop_back();
      ++inProgress_;
    }
    std::unique_ptr<Chunk> chunk;
    bool failed = false;
    try {
      if (storage_) chunk = storage_->load(pos);
      if (chunk) {
        generator_.fillTints(*chunk);
      } else {
        chunk = std::make_unique<Chunk>(pos);
        generator_.generate(*chunk);
      }
    } catch (const std::exception& e) {
      // Never generate in place of a chunk whose save could not be read: a later edit would bury it.
      logError("chunk (" + std::to_string(pos.x) + ", " + std::to_string(pos.z) +
               ") not loaded: " + e.what());
      failed = true;
    }
    std::lock_guard lock(mutex_);
    if (failed) {
      failed_.push_back(pos);
    } else {
      finished_.push_back(std::move(chunk));
    }
    --inProgress_;
  }
}

}  // namespace terrasol
