#include "assets/resource_pack.h"

#include <limits>

#include "core/error.h"
#include "core/json_check.h"
#include "core/log.h"

namespace terrasol {
namespace {

using namespace json_check;

constexpr const char* kBlockDirs[] = {"assets/minecraft/textures/block", "assets/minecraft/textures/blocks"};

enum class NormalConvention { DirectX, OpenGl };
constexpr EnumNames<NormalConvention, 2> kNormalConventions{{"directx", "opengl"}};

// pack.mcmeta is Minecraft's: keys Terrasol does not read (supported_formats, overlays, filter,
// language...) are other readers' and pass unremarked. Only the "terrasol" section is Terrasol's, and a
// key it does not know there is probably a typo: a warning, as the pack loaded before it was checked.
PackInfo parsePack(const json& root, const std::string& file) {
  if (!root.is_object()) expected("", "an object", root);
  const json& pack = required(root, "", "pack");
  if (!pack.is_object()) expected("pack", "an object", pack);
  PackInfo info;
  constexpr std::int64_t kMinInt = std::numeric_limits<int>::min(), kMaxInt = std::numeric_limits<int>::max();
  const json& format = required(pack, "pack", "pack_format");
  info.packFormat = static_cast<int>(wholeNumber(format, "pack.pack_format", kMinInt, kMaxInt));
  if (const json* d = field(pack, "description")) {
    // A plain string, or a JSON text component (kept as its JSON text).
    info.description = d->is_string() ? d->get<std::string>() : d->dump();
  }
  if (const json* t = field(root, "terrasol")) {
    for (const std::string& key : unknownKeys(*t, "terrasol", {"normal_map_convention"})) {
      logWarning(withFile(file, join({key, ": unknown key, ignored; expected \"normal_map_convention\""})));
    }
    if (const json* c = field(*t, "normal_map_convention")) {
      const NormalConvention convention = enumOf(*c, "terrasol.normal_map_convention", kNormalConventions);
      info.openGlNormals = convention == NormalConvention::OpenGl;
    }
  }
  return info;
}

PackInfo parseMcmeta(const std::vector<std::uint8_t>& bytes, const std::string& file) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const json root = parseJson(text, file);
  try {
    return parsePack(root, file);
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

// Minecraft's own assets need no pack.mcmeta: its client jar, or a folder holding its assets/.
bool holdsMinecraftAssets(const PackSource& source) {
  return !source.list("assets/minecraft/blockstates").empty() || !source.list(kBlockDirs[0]).empty();
}

}  // namespace

ResourcePack ResourcePack::open(const std::filesystem::path& path) {
  ResourcePack pack;
  // An extracted assets/ folder itself: its parent is the pack.
  std::error_code ec;
  const bool assetsFolder =
      path.filename() == "assets" && std::filesystem::is_directory(path / "minecraft", ec);
  pack.source_ = PackSource::open(assetsFolder ? path.parent_path() : path);
  const auto mcmeta = pack.source_->read("pack.mcmeta");
  if (mcmeta) {
    pack.info_ = parseMcmeta(*mcmeta, pack.source_->displayName("pack.mcmeta"));
  } else if (holdsMinecraftAssets(*pack.source_)) {
    pack.info_.description = "Minecraft's assets";
  } else {
    throw Error(pack.source_->displayName("pack.mcmeta") + ": missing: not a resource pack");
  }
  for (const char* dir : kBlockDirs) {
    for (const auto& name : pack.source_->list(dir))
      pack.blockFiles_.emplace(name, std::string(dir) + "/" + name);
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

std::optional<PackStack::FoundName> PackStack::findBlockTextureNamed(
    const std::vector<std::string>& names) const {
  for (auto it = packs_.rbegin(); it != packs_.rend(); ++it) {
    for (const std::string& name : names) {
      if (auto path = (*it)->blockTexture(name + ".png")) return FoundName{{it->get(), *path}, name};
    }
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
