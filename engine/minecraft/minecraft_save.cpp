#include "minecraft/minecraft_save.h"

#include <fstream>
#include <regex>

#include "core/error.h"
#include "minecraft/chunk_compression.h"
#include "minecraft/data_versions.h"
#include "minecraft/nbt.h"

namespace terrasol {
namespace {

using nbt::Tag;
using nbt::TagType;

std::vector<std::uint8_t> readBinary(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool holdsRegions(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".mca") return true;
  return false;
}

// Where the overworld's regions are, by the layouts Minecraft has used.
std::filesystem::path findRegionDir(const std::filesystem::path& dir) {
  for (const auto& candidate :
       {dir / "dimensions" / "minecraft" / "overworld" / "region", dir / "region", dir})
    if (holdsRegions(candidate)) return candidate;
  throw Error(dir.string() + ": no Minecraft region files (region/r.X.Z.mca) here");
}

}  // namespace

SaveLevel readLevelDat(const std::filesystem::path& file) {
  const std::vector<std::uint8_t> packed = readBinary(file);
  const std::vector<std::uint8_t> raw = inflateAny(packed, file.string());
  const nbt::Document doc = nbt::parse(raw, file.string());
  SaveLevel level;
  const Tag* data = doc.root.find("Data", TagType::Compound);
  if (!data) throw Error(file.string() + ": no Data compound");
  if (const Tag* v = data->find("DataVersion"); v && v->isInteger())
    level.dataVersion = static_cast<int>(v->integer());
  if (const Tag* version = data->find("Version", TagType::Compound)) {
    if (const Tag* name = version->find("Name", TagType::String)) level.versionName = name->string();
  }
  const Tag* x = data->find("SpawnX");
  const Tag* y = data->find("SpawnY");
  const Tag* z = data->find("SpawnZ");
  if (x && y && z && x->isInteger() && y->isInteger() && z->isInteger())
    level.spawn = glm::ivec3(x->integer(), y->integer(), z->integer());
  if (const Tag* player = data->find("Player", TagType::Compound)) {
    const Tag* pos = player->find("Pos", TagType::List);
    if (pos && pos->items().size() == 3 && pos->listType() == TagType::Double)
      level.player = glm::dvec3(pos->items()[0].real(), pos->items()[1].real(), pos->items()[2].real());
  }
  return level;
}

MinecraftSave::MinecraftSave(const std::filesystem::path& dir) : dir_(dir) {
  if (!std::filesystem::is_directory(dir)) throw Error(dir.string() + ": not a folder");
  const auto levelDat = dir / "level.dat";
  if (std::filesystem::exists(levelDat)) {
    level_ = readLevelDat(levelDat);
    if (level_.dataVersion < kDataVersion1_13) {
      const std::string version = level_.versionName.empty() ? "a version before 1.9" : level_.versionName;
      throw Error(
          levelDat.string() + ": the save is from Minecraft " + version + " (DataVersion " +
          std::to_string(level_.dataVersion) +
          "); Terrasol reads saves from 1.13 on: open it once in Minecraft 1.13 or newer to upgrade it");
    }
  }
  regionDir_ = findRegionDir(dir);
  const std::regex name(R"(r\.(-?\d+)\.(-?\d+)\.mca)");
  for (const auto& entry : std::filesystem::directory_iterator(regionDir_)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, m, name)) continue;
    const int rx = std::stoi(m[1]), rz = std::stoi(m[2]);
    try {
      auto region = std::make_unique<AnvilRegion>(entry.path(), rx, rz);
      for (const std::string& p : region->problems()) problems_.push_back(p);
      regions_.emplace(std::pair{rx, rz}, std::move(region));
    } catch (const Error& e) {
      problems_.push_back(std::string(e.what()) + "; region left out");
    }
  }
}

std::vector<ChunkPos> MinecraftSave::chunks() const {
  std::vector<ChunkPos> out;
  for (const auto& [pos, region] : regions_)
    for (const ChunkPos c : region->chunks()) out.push_back(c);
  return out;
}

bool MinecraftSave::contains(ChunkPos chunk) const {
  const auto it = regions_.find({chunk.x >> 5, chunk.z >> 5});
  return it != regions_.end() && it->second->contains(chunk);
}

std::optional<AnvilChunk> MinecraftSave::load(ChunkPos chunk, BlockStateMapper& mapper,
                                              bool withLight) const {
  const auto it = regions_.find({chunk.x >> 5, chunk.z >> 5});
  if (it == regions_.end()) return std::nullopt;
  const AnvilRegion& region = *it->second;
  const std::optional<std::vector<std::uint8_t>> raw = region.read(chunk);
  if (!raw) return std::nullopt;
  const std::string what = region.describe(chunk);
  const nbt::Document doc = nbt::parse(*raw, what);
  return decodeAnvilChunk(doc.root, chunk, mapper, what, withLight);
}

}  // namespace terrasol
