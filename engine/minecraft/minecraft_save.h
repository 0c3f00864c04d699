#pragma once
// A Minecraft Java save, read-only: a folder with level.dat and region/ (the overworld; 26.1 moves it
// to dimensions/minecraft/overworld/region/), a folder holding region/ alone, or a bare folder of
// r.X.Z.mca files, as tools and servers ship them. Nothing in it is ever written.
//
// Opening reads level.dat (when there is one) and every region's header; chunks are read on demand,
// from any thread. A region whose header cannot be read is reported and left out; the save still opens.

#include <filesystem>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "minecraft/anvil_chunk.h"
#include "minecraft/anvil_region.h"

namespace terrasol {

struct SaveLevel {
  int dataVersion = 0;               // 0: no level.dat, or it does not say
  std::string versionName;           // "1.18.1", or empty
  std::optional<glm::dvec3> player;  // the single player's position
  std::optional<glm::ivec3> spawn;
};

class MinecraftSave {
 public:
  // Throws Error naming the folder when it holds no region files, or when level.dat says the save is
  // from before 1.13 (its version named).
  explicit MinecraftSave(const std::filesystem::path& dir);

  const std::filesystem::path& dir() const { return dir_; }
  const std::filesystem::path& regionDir() const { return regionDir_; }
  const SaveLevel& level() const { return level_; }

  // Every chunk the regions' headers list, region by region.
  std::vector<ChunkPos> chunks() const;
  bool contains(ChunkPos chunk) const;
  // The chunk decoded, or nothing when no region holds it. Throws Error naming the region file, the
  // chunk and what is wrong with it. Thread-safe with one mapper per thread.
  // `withLight`: with the light the save keeps (AnvilChunk::light).
  std::optional<AnvilChunk> load(ChunkPos chunk, BlockStateMapper& mapper, bool withLight = false) const;

  // Regions that could not be opened, and their headers' bad slots.
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::filesystem::path dir_, regionDir_;
  SaveLevel level_;
  std::map<std::pair<int, int>, std::unique_ptr<AnvilRegion>> regions_;
  std::vector<std::string> problems_;
};

// level.dat's facts; throws Error naming the file when it cannot be read.
SaveLevel readLevelDat(const std::filesystem::path& file);

}  // namespace terrasol
