#include "world/chunk_streamer.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>

#include "core/log.h"

namespace terrasol {
namespace {

int chebyshev(ChunkPos a, ChunkPos b) {
  return std::max(std::abs(a.x - b.x), std::abs(a.z - b.z));
}

}  // namespace

ChunkStreamer::ChunkStreamer(World& world, const ChunkGenerator& generator, WorldStorage* storage,
                             int threads, int radius)
    : world_(world), storage_(storage), radius_(radius), loader_(generator, storage, threads) {}

std::vector<ChunkPos> ChunkStreamer::update(ChunkPos center, const std::function<bool()>& more) {
  loader_.setCenter(center);
  for (auto& chunk : loader_.takeFinished()) ready_.push_back(std::move(chunk));
  std::erase_if(ready_, [&](const std::unique_ptr<Chunk>& c) {
    const bool drop = chebyshev(c->pos(), center) > radius_ + 1;  // no longer wanted
    if (drop) requested_.erase(c->pos());
    return drop;
  });
  // Farthest first in the vector, so the closest is taken from the back.
  std::sort(ready_.begin(), ready_.end(), [&](const auto& a, const auto& b) {
    return chebyshev(a->pos(), center) > chebyshev(b->pos(), center);
  });
  std::vector<ChunkPos> added;
  while (!ready_.empty() && (!more || added.empty() || more())) {
    std::unique_ptr<Chunk> chunk = std::move(ready_.back());
    ready_.pop_back();
    const ChunkPos pos = chunk->pos();
    requested_.erase(pos);
    if (world_.isLoaded(pos)) continue;
    world_.insertChunk(std::move(chunk));
    if (loaded_) loaded_(pos);
    added.push_back(pos);
  }

  // Unreadable chunks are asked for again on a later update (the region may come back).
  for (ChunkPos pos : loader_.takeFailed()) requested_.erase(pos);

  // Unload what is out of range; edited chunks are saved first.
  std::vector<ChunkPos> far;
  std::as_const(world_).forEachChunk([&](const Chunk& c) {
    if (chebyshev(c.pos(), center) > radius_ + 1) far.push_back(c.pos());
  });
  for (ChunkPos pos : far) {
    Chunk* chunk = world_.chunk(pos);
    if (storage_ && chunk->modified()) {
      try {
        storage_->save(*chunk);  // before removing: a failed save must not lose the edits
        chunk->setModified(false);
      } catch (const std::exception& e) {
        logError(std::string("keeping an unsaved chunk loaded: ") + e.what());
        continue;
      }
    }
    if (unloading_) unloading_(pos);
    world_.removeChunk(pos);
  }
  loader_.cancelIf([&](ChunkPos pos) {
    const bool drop = chebyshev(pos, center) > radius_ + 1;
    if (drop) requested_.erase(pos);
    return drop;
  });

  for (int dz = -radius_; dz <= radius_; ++dz)
    for (int dx = -radius_; dx <= radius_; ++dx) {
      const ChunkPos pos{center.x + dx, center.z + dz};
      if (!world_.isLoaded(pos) && requested_.insert(pos).second) loader_.request(pos);
    }
  return added;
}

void ChunkStreamer::saveAll() {
  if (!storage_) return;
  world_.forEachChunk([&](Chunk& c) {
    if (!c.modified()) return;
    storage_->save(c);
    c.setModified(false);
  });
  storage_->flush();
}

}  // namespace terrasol
