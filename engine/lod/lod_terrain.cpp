#include "lod/lod_terrain.h"

#include <algorithm>
#include <utility>

#include "core/thread_priority.h"

namespace terrasol {
namespace {

std::tuple<int, int, int> tileKey(LodTileKey k) {
  return {k.level, k.x, k.z};
}

}  // namespace

LodTerrain::LodTerrain(LodTileSource source, LodPalette palette, LodLevels levels, int threads)
    : source_(std::move(source)), palette_(std::move(palette)), levels_(levels) {
  for (int i = 0; i < threads; ++i) workers_.emplace_back([this](std::stop_token stop) { work(stop); });
}

LodTerrain::~LodTerrain() {
  for (std::jthread& w : workers_) w.request_stop();
  wake_.notify_all();
  workers_.clear();
}

void LodTerrain::update(const LodView& view, bool wait) {
  std::vector<LodSelected> selected = selectLodTiles(view, levels_);
  std::unique_lock lock(mutex_);
  if (selected != wanted_ || wantedChanged_) {
    for (const LodSelected& s : queue_) building_.erase(meshKey(s));
    queue_.clear();
    wanted_ = std::move(selected);
    startMissing();
    finishIfReady();
  }
  if (workers_.empty()) {
    while (!queue_.empty()) {
      const LodSelected s = queue_.front();
      queue_.pop_front();
      lock.unlock();
      build(s);
      lock.lock();
    }
  } else if (wait) {
    done_.wait(lock, [&] { return queue_.empty() && building_.empty(); });
  }
}

std::optional<LodSet> LodTerrain::takeSet() {
  std::lock_guard lock(mutex_);
  return std::exchange(ready_, std::nullopt);
}

void LodTerrain::invalidate(int x, int z) {
  std::lock_guard lock(mutex_);
  ++edits_;
  for (int level = 0; level <= kLodMaxLevel; ++level) {
    const int span = kLodTileCells << level;
    const LodTileKey key{level, x >= 0 ? x / span : (x + 1) / span - 1,
                         z >= 0 ? z / span : (z + 1) / span - 1};
    tiles_.erase(tileKey(key));
    for (const bool walls : {false, true}) meshes_.erase({level, key.x, key.z, walls});
    for (const LodSelected& s : wanted_)
      if (s.key == key) wantedChanged_ = true;
  }
}

LodTerrainStats LodTerrain::stats() const {
  std::lock_guard lock(mutex_);
  LodTerrainStats s;
  s.tiles = static_cast<int>(shown_.size());
  std::set<int> levels;
  for (const LodSelected& t : shown_) {
    levels.insert(t.key.level);
    if (const auto it = meshes_.find(meshKey(t)); it != meshes_.end())
      s.meshBytes += it->second->vertices.size() * sizeof(LodVertex);
  }
  s.levels = static_cast<int>(levels.size());
  s.cachedBytes = tiles_.size() * sizeof(LodTile);
  for (const auto& [k, m] : meshes_) s.cachedBytes += m->vertices.capacity() * sizeof(LodVertex);
  s.pending = static_cast<int>(queue_.size() + building_.size());
  return s;
}

void LodTerrain::work(std::stop_token stop) {
  lowerThisThreadsPriority();  // as the chunk and mesh workers: the frame comes first
  std::unique_lock lock(mutex_);
  while (!stop.stop_requested()) {
    if (!wake_.wait(lock, stop, [&] { return !queue_.empty(); })) return;
    const LodSelected s = queue_.front();
    queue_.pop_front();
    lock.unlock();
    build(s);
    lock.lock();
  }
}

void LodTerrain::build(const LodSelected& s) {
  std::shared_ptr<const LodTile> tile;
  std::uint64_t edits = 0;
  {
    std::lock_guard lock(mutex_);
    edits = edits_;
    if (const auto it = tiles_.find(tileKey(s.key)); it != tiles_.end()) tile = it->second;
  }
  if (!tile) tile = std::make_shared<const LodTile>(source_(s.key));
  auto mesh = std::make_shared<const LodMesh>(meshLodTile(*tile, palette_, s.touchesFullDetail));
  std::lock_guard lock(mutex_);
  building_.erase(meshKey(s));
  if (edits == edits_) {
    tiles_.emplace(tileKey(s.key), tile);
    meshes_[meshKey(s)] = std::move(mesh);
  } else {
    startMissing();  // an edit came while it was built: build it again if it is still wanted
  }
  finishIfReady();
  done_.notify_all();
}

void LodTerrain::startMissing() {
  for (const LodSelected& s : wanted_) {
    const MeshKey k = meshKey(s);
    if (meshes_.contains(k) || building_.contains(k)) continue;
    building_.insert(k);
    queue_.push_back(s);
  }
  wake_.notify_all();
}

void LodTerrain::finishIfReady() {
  if (wanted_ == shown_ && !wantedChanged_) return;
  LodSet set;
  for (const LodSelected& s : wanted_) {
    const auto it = meshes_.find(meshKey(s));
    if (it == meshes_.end()) return;
    set.meshes.push_back(it->second);
  }
  set.generation = ++generation_;
  ready_ = std::move(set);
  shown_ = wanted_;
  wantedChanged_ = false;
  // Keep only what the set shown holds.
  std::set<MeshKey> keep;
  std::set<std::tuple<int, int, int>> keepTiles;
  for (const LodSelected& s : shown_) keep.insert(meshKey(s)), keepTiles.insert(tileKey(s.key));
  std::erase_if(meshes_, [&](const auto& m) { return !keep.contains(m.first); });
  std::erase_if(tiles_, [&](const auto& t) { return !keepTiles.contains(t.first); });
}

}  // namespace terrasol
