#include "world/world_storage.h"

#include <fstream>

#include "core/error.h"
#include "world/chunk_codec.h"

namespace terrasol {

WorldStorage::WorldStorage(std::filesystem::path dir, const BlockRegistry& blocks)
    : dir_(std::move(dir)), blocks_(&blocks) {
  std::error_code ec;
  std::filesystem::create_directories(dir_ / "region", ec);
  if (ec) throw Error(locate(dir_, 0, "cannot create the world directory: " + ec.message()));
}

RegionFile& WorldStorage::region(RegionPos pos) {
  lastUse_[{pos.x, pos.z}] = ++useClock_;
  if (!regions_.contains({pos.x, pos.z}) && regions_.size() >= kMaxOpenRegions) {
    auto oldest = regions_.begin();
    for (auto it = regions_.begin(); it != regions_.end(); ++it) {
      if (lastUse_[it->first] < lastUse_[oldest->first]) oldest = it;
    }
    oldest->second->sync();
    lastUse_.erase(oldest->first);
    regions_.erase(oldest);
  }
  auto& slot = regions_[{pos.x, pos.z}];
  if (!slot) {
    const auto path = dir_ / "region" / ("r." + std::to_string(pos.x) + "." + std::to_string(pos.z) + ".tsr");
    slot = std::make_unique<RegionFile>(path, pos);
    problems_.insert(problems_.end(), slot->problems().begin(), slot->problems().end());
  }
  return *slot;
}

std::unique_ptr<Chunk> WorldStorage::load(ChunkPos pos) {
  std::lock_guard lock(mutex_);
  RegionFile& file = region(RegionPos::of(pos));
  const auto payload = file.read(pos);
  if (!payload) return nullptr;
  const std::string where =
      file.path().string() + ": chunk (" + std::to_string(pos.x) + ", " + std::to_string(pos.z) + ")";
  try {
    std::vector<std::string> unknown;
    auto chunk = decodeChunk(pos, payload->data(), payload->size(), *blocks_, &unknown);
    for (const auto& name : unknown) {
      // A known block with an unknown property or value opens in its default state.
      const BlockId state = blocks_->find(name);
      problems_.push_back(state == kAir ? where + ": unknown block '" + name + "' loaded as air"
                                        : where + ": unknown block state '" + name + "' loaded as " +
                                              blocks_->stateName(state));
    }
    chunk->setModified(false);
    return chunk;
  } catch (const Error& e) {
    // The checksum matched, so the bytes are as written: a bug or a newer version wrote them.
    // Kept aside: a later save of this chunk would otherwise let compaction drop these bytes.
    const auto aside = std::filesystem::path(file.path().string() + ".corrupt") /
                       ("chunk_" + std::to_string(pos.x) + "_" + std::to_string(pos.z) + "_undecodable.bin");
    std::error_code ec;
    std::filesystem::create_directories(aside.parent_path(), ec);
    std::ofstream out(aside, std::ios::binary);
    out.write(reinterpret_cast<const char*>(payload->data()), static_cast<std::streamsize>(payload->size()));
    const bool kept = !ec && out.good();
    problems_.push_back(where + ": cannot decode (" + e.what() + ")" +
                        (kept ? "; bytes kept in " + aside.string() : "; could not keep its bytes aside"));
    return nullptr;
  }
}

void WorldStorage::save(const Chunk& chunk) {
  const auto payload = encodeChunk(chunk, *blocks_);  // outside the lock: the slow part
  std::lock_guard lock(mutex_);
  RegionFile& file = region(RegionPos::of(chunk.pos()));
  file.write(chunk.pos(), payload);
  file.compactIfWasteful();
}

void WorldStorage::flush() {
  std::lock_guard lock(mutex_);
  for (auto& [pos, file] : regions_) file->sync();
}

std::vector<std::string> WorldStorage::problems() const {
  std::lock_guard lock(mutex_);
  return problems_;
}

}  // namespace terrasol
