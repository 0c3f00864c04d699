#include "assets/resource_pack.h"

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace terrasol {
namespace {

using nlohmann::json;

constexpr const char* kBlockDirs[] = {"assets/minecraft/textures/block", "assets/minecraft/textures/blocks"};

PackInfo parseMcmeta(const std::vector<std::uint8_t>& bytes, const std::string& file) {
  json root;
  try {
    root = json::parse(bytes.begin(), bytes.end());
  } catch (const json::parse_error& e) {
    throw Error(file + ": invalid JSON: " + e.what());
  }
  if (!root.is_object() || !root.contains("pack") || !root["pack"].is_object()) {
    throw Error(file + ": expected {\"pack\": {\"pack_format\": N, \"description\": ...}}");
  }
  const json& pack = root["pack"];
  PackInfo info;
  if (!pack.contains("pack_format") || !pack["pack_format"].is_number_integer()) {
    throw Error(file + ": pack.pack_format must be an integer");
  }
  info.packFormat = pack["pack_format"].get<int>();
  if (pack.contains("description")) {
    // A plain string, or a JSON text component (kept as its JSON text).
    info.description = pack["description"].is_string() ? pack["description"].get<std::string>() : pack["description"].dump();
  }
  if (root.contains("terrasol")) {
    const json& t = root["terrasol"];
    if (!t.is_object()) throw Error(file + ": \"terrasol\" must be an object");
    if (t.contains("normal_map_convention")) {
      const json& c = t["normal_map_convention"];
      if (!c.is_string() || (c != "directx" && c != "opengl")) {
        throw Error(file + ": terrasol.normal_map_convention must be \"directx\" or \"opengl\"");
      }
      info.openGlNormals = c == "opengl";
    }
  }
  return info;
}

}  // namespace

ResourcePack ResourcePack::open(const std::filesystem::path& path) {
  ResourcePack pack;
  pack.source_ = PackSource::open(path);
  const auto mcmeta = pack.source_->read("pack.mcmeta");
  if (!mcmeta) throw Error(pack.source_->displayName("pack.mcmeta") + ": missing: not a resource pack");
  pack.info_ = parseMcmeta(*mcmeta, pack.source_->displayName("pack.mcmeta"));
  for (const char* dir : kBlockDirs) {
    for (const auto& name : pack.source_->list(dir)) pack.blockFiles_.emplace(name, std::string(dir) + "/" + name);
  }
  return pack;
}

std::optional<std::string> ResourcePack::blockTexture(const std::string& file) const {
  const auto it = blockFiles_.find(file);
  return it == blockFiles_.end() ? std::nullopt : std::optional(it->second);
}

std::vector<std::string> ResourcePack::blockTextureFiles() const {
  std::vector<std::string> files;
  for (const auto& [name, path] : blockFiles_) {
    if (name.size() > 4 && name.ends_with(".png")) files.push_back(name);
  }
  return files;
}

std::optional<PackStack::Found> PackStack::findBlockTexture(const std::string& file) const {
  for (auto it = packs_.rbegin(); it != packs_.rend(); ++it) {
    if (auto path = (*it)->blockTexture(file)) return Found{it->get(), *path};
  }
  return std::nullopt;
}

std::optional<PackStack::Found> PackStack::find(const std::string& path) const {
  for (auto it = packs_.rbegin(); it != packs_.rend(); ++it) {
    if ((*it)->files().read(path)) return Found{it->get(), path};
  }
  return std::nullopt;
}

}  // namespace terrasol
