#include "world/block_registry.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace terrasol {
namespace {

using nlohmann::json;

template <class Enum, std::size_t N>
Enum parseEnum(const json& value, const std::array<std::pair<const char*, Enum>, N>& names, const std::string& where) {
  if (!value.is_string()) throw Error(where + " must be a string");
  for (const auto& [name, e] : names) {
    if (value.get<std::string>() == name) return e;
  }
  std::string list;
  for (const auto& [name, e] : names) list += (list.empty() ? "" : ", ") + std::string(name);
  throw Error(where + " is '" + value.get<std::string>() + "', expected one of " + list);
}

std::vector<std::string> textureCandidates(const json& value, const std::string& where) {
  std::vector<std::string> names;
  if (value.is_string()) names.push_back(value.get<std::string>());
  if (value.is_array()) {
    for (const auto& v : value) {
      if (!v.is_string()) throw Error(where + " must list texture names as strings");
      names.push_back(v.get<std::string>());
    }
  }
  if (names.empty()) throw Error(where + " must be a texture name or a non-empty list of names");
  return names;
}

// "all", then "side"/"end", then "top"/"bottom", then single faces: later keys refine earlier ones.
FaceTextures parseTextures(const json& textures, const std::string& where) {
  if (!textures.is_object()) throw Error(where + " must be an object");
  static const std::vector<std::pair<const char*, std::vector<int>>> kKeys = {
      {"all", {0, 1, 2, 3, 4, 5}}, {"side", {0, 1, 4, 5}}, {"end", {2, 3}}, {"top", {3}},   {"bottom", {2}},
      {"west", {0}},               {"east", {1}},          {"down", {2}},   {"up", {3}},    {"north", {4}},
      {"south", {5}},
  };
  for (const auto& [key, value] : textures.items()) {
    const bool known = std::any_of(kKeys.begin(), kKeys.end(), [&](const auto& k) { return key == k.first; });
    if (!known) throw Error(where + " has unknown face '" + key + "'");
  }
  FaceTextures faces;
  for (const auto& [key, indices] : kKeys) {
    if (!textures.contains(key)) continue;
    const auto names = textureCandidates(textures[key], where + "." + key);
    for (int i : indices) faces[static_cast<std::size_t>(i)] = names;
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (faces[i].empty()) throw Error(where + " leaves a face without a texture (give \"all\" or every face)");
  }
  return faces;
}

int parseLevel(const json& block, const char* key, int fallback, const std::string& where) {
  if (!block.contains(key)) return fallback;
  const json& v = block[key];
  if (!v.is_number_integer() || v.get<int>() < 0 || v.get<int>() > 15) {
    throw Error(where + "." + key + " must be an integer 0..15");
  }
  return v.get<int>();
}

BlockType parseBlock(const json& block, const std::string& where) {
  if (!block.is_object()) throw Error(where + " must be an object");
  if (!block.contains("name") || !block["name"].is_string() || block["name"].get<std::string>().empty()) {
    throw Error(where + ".name must be a non-empty string");
  }
  BlockType type;
  type.name = block["name"].get<std::string>();
  const std::string at = where + " (" + type.name + ")";
  static constexpr std::array<std::pair<const char*, BlockShape>, 5> kShapes = {{{"none", BlockShape::None},
                                                                                  {"cube", BlockShape::Cube},
                                                                                  {"cross", BlockShape::Cross},
                                                                                  {"liquid", BlockShape::Liquid},
                                                                                  {"torch", BlockShape::Torch}}};
  static constexpr std::array<std::pair<const char*, RenderLayer>, 3> kLayers = {
      {{"opaque", RenderLayer::Opaque}, {"cutout", RenderLayer::Cutout}, {"translucent", RenderLayer::Translucent}}};
  static constexpr std::array<std::pair<const char*, Tint>, 4> kTints = {
      {{"none", Tint::None}, {"grass", Tint::Grass}, {"foliage", Tint::Foliage}, {"water", Tint::Water}}};

  type.shape = block.contains("shape") ? parseEnum(block["shape"], kShapes, at + ".shape") : BlockShape::Cube;
  if (type.shape != BlockShape::None) {
    const RenderLayer defaultLayer = type.shape == BlockShape::Cube ? RenderLayer::Opaque : RenderLayer::Cutout;
    type.layer = block.contains("layer") ? parseEnum(block["layer"], kLayers, at + ".layer") : defaultLayer;
    if (!block.contains("textures")) throw Error(at + " needs \"textures\"");
    type.textures = parseTextures(block["textures"], at + ".textures");
  }
  type.tint = block.contains("tint") ? parseEnum(block["tint"], kTints, at + ".tint") : Tint::None;
  type.opacity = static_cast<std::uint8_t>(parseLevel(block, "opacity", type.isOpaqueCube() ? 15 : 0, at));
  type.emission = static_cast<std::uint8_t>(parseLevel(block, "emission", 0, at));
  return type;
}

}  // namespace

BlockRegistry BlockRegistry::fromFile(const std::filesystem::path& file) {
  return fromJson(readTextFile(file), file.string());
}

BlockRegistry BlockRegistry::fromJson(std::string_view text, const std::string& fileName) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(fileName + ": invalid JSON: " + e.what());
  }
  try {
    if (!root.is_object() || !root.contains("blocks") || !root["blocks"].is_array()) {
      throw Error("expected an object with a \"blocks\" array");
    }
    BlockRegistry registry;
    const json& blocks = root["blocks"];
    if (blocks.size() > 65535) throw Error("more than 65535 blocks");
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      BlockType type = parseBlock(blocks[i], "blocks[" + std::to_string(i) + "]");
      if (i == 0 && (type.name != "air" || type.shape != BlockShape::None)) {
        throw Error("blocks[0] must be \"air\" with shape \"none\"");
      }
      if (!registry.byName_.emplace(type.name, static_cast<BlockId>(i)).second) {
        throw Error("blocks[" + std::to_string(i) + "]: duplicate block name '" + type.name + "'");
      }
      registry.opacity_.push_back(type.opacity);
      registry.emission_.push_back(type.emission);
      registry.opaqueCube_.push_back(type.isOpaqueCube() ? 1 : 0);
      registry.types_.push_back(std::move(type));
    }
    if (registry.types_.empty()) throw Error("\"blocks\" is empty (air must come first)");
    return registry;
  } catch (const Error& e) {
    throw Error(fileName + ": " + e.what());
  }
}

BlockId BlockRegistry::id(std::string_view name) const {
  bool found = false;
  const BlockId result = find(name, &found);
  if (!found) throw Error("unknown block '" + std::string(name) + "'");
  return result;
}

BlockId BlockRegistry::find(std::string_view name, bool* found) const {
  const auto it = byName_.find(std::string(name));
  if (found) *found = it != byName_.end();
  return it == byName_.end() ? kAir : it->second;
}

}  // namespace terrasol
