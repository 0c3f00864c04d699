#include "world_choice.h"

#include <cstdint>
#include <cstdio>

namespace terrasol {
namespace {

bool holdsRegionFiles(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".mca") return true;
  return false;
}

}  // namespace

bool isMinecraftSave(const std::filesystem::path& path) {
  if (!std::filesystem::is_directory(path) || std::filesystem::exists(path / "level.json")) return false;
  return std::filesystem::exists(path / "level.dat") || holdsRegionFiles(path / "region") ||
         holdsRegionFiles(path);
}

WorldChoice chooseWorld(const std::filesystem::path& path, const std::filesystem::path& worlds) {
  if (!isMinecraftSave(path)) return {path, {}};
  const std::filesystem::path save = std::filesystem::absolute(path).lexically_normal();
  std::string name = save.filename().string();
  if (name.empty()) name = save.parent_path().filename().string();
  // Two saves of one name in different places keep apart: FNV-1a of the path, the same on every run.
  std::uint32_t hash = 2166136261u;
  for (const char c : save.string()) hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
  char tag[9];
  std::snprintf(tag, sizeof tag, "%08x", static_cast<unsigned>(hash));
  return {worlds / ("minecraft-" + name + "-" + tag), save};
}

}  // namespace terrasol
