#pragma once
// A world's directory on disk:
//   DIR/level.json            seed, generator, time, player (level.h)
//   DIR/region/r.X.Z.tsr      chunks of region (X, Z) (region_file.h)
// Only chunks that were edited are saved; untouched ones regenerate identically from the seed.
// Thread-safe: loader threads read while the main thread saves.

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "world/block_registry.h"
#include "world/chunk.h"
#include "world/region_file.h"

namespace terrasol {

class WorldStorage {
 public:
  // Creates DIR and DIR/region when missing.
  WorldStorage(std::filesystem::path dir, const BlockRegistry& blocks);

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path levelFile() const { return dir_ / "level.json"; }

  // The saved chunk, or null when it was never saved or its record is corrupt (see problems()).
  std::unique_ptr<Chunk> load(ChunkPos pos);
  void save(const Chunk& chunk);
  // Makes every save so far durable.
  void flush();

  // Everything found wrong so far: corrupt records, torn saves, undecodable chunks. Each names the
  // file, the chunk and what is wrong.
  std::vector<std::string> problems() const;

 private:
  RegionFile& region(RegionPos pos);  // caller holds mutex_
  // Open region files beyond this are closed, least recently used first (file descriptors and indexes
  // stay bounded however far the player travels).
  static constexpr std::size_t kMaxOpenRegions = 32;
  std::uint64_t useClock_ = 0;
  std::map<std::pair<int, int>, std::uint64_t> lastUse_;

  std::filesystem::path dir_;
  const BlockRegistry* blocks_;
  mutable std::mutex mutex_;
  std::map<std::pair<int, int>, std::unique_ptr<RegionFile>> regions_;
  std::vector<std::string> problems_;
};

}  // namespace terrasol
