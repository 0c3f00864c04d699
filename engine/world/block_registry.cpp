#include "world/block_registry.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace terrasol {
namespace {

using nlohmann::json;

template <class Enum, std::size_t N>
Enum parseEnum(const json& value, const std::array<std::pair<const char*, Enum>, N>& names,
               const std::string& where) {
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
      {"all", {0, 1, 2, 3, 4, 5}},
      {"side", {0, 1, 4, 5}},
      {"end", {2, 3}},
      {"top", {3}},
      {"bottom", {2}},
      {"west", {0}},
      {"east", {1}},
      {"down", {2}},
      {"up", {3}},
      {"north", {4}},
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
    if (faces[i].empty())
      throw Error(where + " leaves a face without a texture (give \"all\" or every face)");
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

// "properties": {"axis": ["y", "x", "z"]} and "default": {"axis": "y"}: the block's states.
void parseProperties(const json& block, BlockType& type, const std::string& where) {
  if (!block.contains("properties")) {
    if (block.contains("default")) throw Error(where + ".default needs \"properties\"");
    return;
  }
  const json& props = block["properties"];
  if (!props.is_object() || props.empty()) throw Error(where + ".properties must be a non-empty object");
  std::size_t states = 1;
  for (const auto& [name, values] : props.items()) {
    const std::string at = where + ".properties." + name;
    if (!values.is_array() || values.empty()) throw Error(at + " must be a non-empty array of values");
    BlockProperty p{name, {}};
    for (const json& v : values) {
      if (!v.is_string() || v.get<std::string>().empty())
        throw Error(at + " must list values as non-empty strings");
      const std::string value = v.get<std::string>();
      if (value.find_first_of("[],=") != std::string::npos ||
          name.find_first_of("[],=") != std::string::npos) {
        throw Error(at + ": names and values may not contain '[', ']', ',' or '='");
      }
      if (std::find(p.values.begin(), p.values.end(), value) != p.values.end()) {
        throw Error(at + " lists '" + value + "' twice");
      }
      p.values.push_back(value);
    }
    states *= p.values.size();
    if (states > 4096) throw Error(where + ".properties make more than 4096 states");
    type.properties.push_back(std::move(p));
  }
  type.stateCount = static_cast<std::uint16_t>(states);
}

// The state's offset among its block's states: the last property counts fastest.
std::size_t stateOffset(const BlockType& type, const std::vector<std::size_t>& valueIndices) {
  std::size_t offset = 0;
  for (std::size_t i = 0; i < type.properties.size(); ++i) {
    offset = offset * type.properties[i].values.size() + valueIndices[i];
  }
  return offset;
}

std::vector<std::size_t> valueIndicesOf(const BlockType& type, std::size_t offset) {
  std::vector<std::size_t> indices(type.properties.size());
  for (std::size_t i = type.properties.size(); i-- > 0;) {
    indices[i] = offset % type.properties[i].values.size();
    offset /= type.properties[i].values.size();
  }
  return indices;
}

std::size_t valueIndex(const BlockProperty& p, std::string_view value) {
  return static_cast<std::size_t>(std::find(p.values.begin(), p.values.end(), value) - p.values.begin());
}

// The default state's offset: "default" names values, the rest take their first.
std::size_t defaultOffset(const json& block, const BlockType& type, const std::string& where) {
  std::vector<std::size_t> indices(type.properties.size(), 0);
  if (!block.contains("default")) return 0;
  const json& d = block["default"];
  if (!d.is_object()) throw Error(where + ".default must be an object");
  for (const auto& [name, value] : d.items()) {
    const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                                [&](const BlockProperty& q) { return q.name == name; });
    if (p == type.properties.end()) throw Error(where + ".default." + name + " is not one of its properties");
    if (!value.is_string() || valueIndex(*p, value.get<std::string>()) == p->values.size()) {
      throw Error(where + ".default." + name + " must be one of the property's values");
    }
    indices[static_cast<std::size_t>(p - type.properties.begin())] = valueIndex(*p, value.get<std::string>());
  }
  return stateOffset(type, indices);
}

std::string optionalString(const json& block, const char* key, const std::string& where) {
  if (!block.contains(key)) return {};
  if (!block[key].is_string()) throw Error(where + "." + key + " must be a string");
  return block[key].get<std::string>();
}

void parseGameplay(const json& block, BlockType& type, const std::string& at) {
  static constexpr std::array<const char*, 10> kPlacements = {
      "stairs", "slab", "axis", "facing", "facing_back", "door", "trapdoor", "wall", "torch", "layers"};
  type.placement = optionalString(block, "placement", at);
  if (!type.placement.empty() &&
      std::find(kPlacements.begin(), kPlacements.end(), type.placement) == kPlacements.end()) {
    throw Error(at + ".placement: unknown rule '" + type.placement +
                "' (stairs, slab, axis, facing, facing_back, door, trapdoor, wall, torch or layers)");
  }
  type.wallVariant = optionalString(block, "wall_variant", at);
  type.connects = optionalString(block, "connects", at);
  if (!type.connects.empty() && type.connects != "fence" && type.connects != "pane" &&
      type.connects != "wall" && type.connects != "gate") {
    throw Error(at + ".connects: unknown kind '" + type.connects + "' (fence, pane, wall or gate)");
  }
  if (block.contains("opens")) {
    if (!block["opens"].is_boolean()) throw Error(at + ".opens must be true or false");
    type.opens = block["opens"].get<bool>();
  }
  if (block.contains("collision")) {
    const json& c = block["collision"];
    if (!c.is_object()) throw Error(at + ".collision must be an object");
    if (c.contains("height")) {
      if (!c["height"].is_number_integer() || c["height"].get<int>() < 1 || c["height"].get<int>() > 32) {
        throw Error(at + ".collision.height must be a whole number of 1/16 blocks, 1..32");
      }
      type.collisionHeight = static_cast<std::uint8_t>(c["height"].get<int>());
    }
    type.passableWhen = optionalString(c, "none_when", at + ".collision");
  }
}

BlockType parseBlock(const json& block, const std::string& where) {
  if (!block.is_object()) throw Error(where + " must be an object");
  if (!block.contains("name") || !block["name"].is_string() || block["name"].get<std::string>().empty()) {
    throw Error(where + ".name must be a non-empty string");
  }
  BlockType type;
  type.name = block["name"].get<std::string>();
  const std::string at = where + " (" + type.name + ")";
  static constexpr std::array<std::pair<const char*, BlockShape>, 6> kShapes = {
      {{"none", BlockShape::None},
       {"cube", BlockShape::Cube},
       {"cross", BlockShape::Cross},
       {"liquid", BlockShape::Liquid},
       {"torch", BlockShape::Torch},
       {"model", BlockShape::Model}}};
  static constexpr std::array<std::pair<const char*, RenderLayer>, 3> kLayers = {
      {{"opaque", RenderLayer::Opaque},
       {"cutout", RenderLayer::Cutout},
       {"translucent", RenderLayer::Translucent}}};
  static constexpr std::array<std::pair<const char*, Tint>, kTintCount> kTints = {{{"none", Tint::None},
                                                                                  {"grass", Tint::Grass},
                                                                                  {"foliage", Tint::Foliage},
                                                                                  {"water", Tint::Water},
                                                                                  {"birch", Tint::Birch},
                                                                                  {"spruce", Tint::Spruce}}};

  type.shape = block.contains("shape") ? parseEnum(block["shape"], kShapes, at + ".shape") : BlockShape::Cube;
  if (type.shape != BlockShape::None) {
    const RenderLayer defaultLayer = type.shape == BlockShape::Cube || type.shape == BlockShape::Model
                                         ? RenderLayer::Opaque
                                         : RenderLayer::Cutout;
    type.layer = block.contains("layer") ? parseEnum(block["layer"], kLayers, at + ".layer") : defaultLayer;
    // A model block's textures come from its models (assets/minecraft/blockstates/<name>.json).
    if (type.shape != BlockShape::Model) {
      if (!block.contains("textures")) throw Error(at + " needs \"textures\"");
      type.textures = parseTextures(block["textures"], at + ".textures");
    } else if (block.contains("textures")) {
      throw Error(at + ": a model block takes its textures from its models, not \"textures\"");
    }
  }
  type.tint = block.contains("tint") ? parseEnum(block["tint"], kTints, at + ".tint") : Tint::None;
  type.opacity = static_cast<std::uint8_t>(parseLevel(block, "opacity", type.isOpaqueCube() ? 15 : 0, at));
  type.emission = static_cast<std::uint8_t>(parseLevel(block, "emission", 0, at));
  parseGameplay(block, type, at);
  if (block.contains("shape_occludes_light")) {
    if (!block["shape_occludes_light"].is_boolean())
      throw Error(at + ".shape_occludes_light must be true or false");
    type.shapeOccludesLight = block["shape_occludes_light"].get<bool>();
  }
  parseProperties(block, type, at);
  if (!type.passableWhen.empty()) {
    const auto eq = type.passableWhen.find('=');
    const auto property =
        std::find_if(type.properties.begin(), type.properties.end(), [&](const BlockProperty& p) {
          return eq != std::string::npos && p.name == type.passableWhen.substr(0, eq);
        });
    if (property == type.properties.end() ||
        std::find(property->values.begin(), property->values.end(), type.passableWhen.substr(eq + 1)) ==
            property->values.end()) {
      throw Error(at + ".collision.none_when: '" + type.passableWhen +
                  "' is not one of its property=value pairs");
    }
  }
  type.defaultState = static_cast<BlockId>(defaultOffset(block, type, at));  // made absolute by the registry
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
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      BlockType type = parseBlock(blocks[i], "blocks[" + std::to_string(i) + "]");
      if (i == 0 && (type.name != "air" || type.shape != BlockShape::None || type.stateCount != 1)) {
        throw Error("blocks[0] must be \"air\" with shape \"none\" and no properties");
      }
      if (registry.blockOf_.size() + type.stateCount > 65535) throw Error("more than 65535 block states");
      if (!registry.byName_.emplace(type.name, static_cast<BlockId>(i)).second) {
        throw Error("blocks[" + std::to_string(i) + "]: duplicate block name '" + type.name + "'");
      }
      type.firstState = static_cast<BlockId>(registry.blockOf_.size());
      type.defaultState = static_cast<BlockId>(type.firstState + type.defaultState);
      for (std::uint16_t s = 0; s < type.stateCount; ++s) {
        registry.blockOf_.push_back(static_cast<std::uint16_t>(i));
        registry.opacity_.push_back(type.opacity);
        registry.emission_.push_back(type.emission);
        registry.opaqueCube_.push_back(type.isOpaqueCube() ? 1 : 0);
      }
      registry.types_.push_back(std::move(type));
    }
    if (registry.types_.empty()) throw Error("\"blocks\" is empty (air must come first)");
    for (const BlockType& type : registry.types_) {
      if (!type.wallVariant.empty() && !registry.byName_.contains(type.wallVariant)) {
        throw Error(type.name + ".wall_variant: no block is named '" + type.wallVariant + "'");
      }
    }
    return registry;
  } catch (const Error& e) {
    throw Error(fileName + ": " + e.what());
  }
}

BlockId BlockRegistry::id(std::string_view name) const {
  bool found = false;
  std::string problem;
  const BlockId result = find(name, &found, &problem);
  if (!found) throw Error(problem);
  return result;
}

BlockId BlockRegistry::find(std::string_view name, bool* found, std::string* problem) const {
  const auto report = [&](BlockId state, const std::string& what) {
    if (found) *found = false;
    if (problem) *problem = what;
    return state;
  };
  const std::size_t open = name.find('[');
  const std::string blockName(name.substr(0, open));
  const auto it = byName_.find(blockName);
  if (it == byName_.end()) return report(kAir, "unknown block '" + blockName + "'");
  const BlockType& type = types_[it->second];
  if (found) *found = true;
  if (open == std::string_view::npos) return type.defaultState;
  if (name.back() != ']')
    return report(type.defaultState, "'" + std::string(name) + "': expected ']' at the end");
  std::vector<std::size_t> indices = valueIndicesOf(type, type.defaultState - type.firstState);
  const std::string_view list = name.substr(open + 1, name.size() - open - 2);
  std::size_t start = 0;
  while (start <= list.size() && !list.empty()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view pair = list.substr(start, comma - start);
    const std::size_t eq = pair.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == pair.size()) {
      return report(type.defaultState,
                    "'" + std::string(name) + "': expected property=value, not '" + std::string(pair) + "'");
    }
    const std::string_view key = pair.substr(0, eq), value = pair.substr(eq + 1);
    const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                                [&](const BlockProperty& q) { return q.name == key; });
    if (p == type.properties.end()) {
      return report(type.defaultState, "'" + std::string(name) + "': " + type.name + " has no property '" +
                                           std::string(key) + "'");
    }
    const std::size_t v = valueIndex(*p, value);
    if (v == p->values.size()) {
      std::string values;
      for (const std::string& s : p->values) values += (values.empty() ? "" : ", ") + s;
      return report(type.defaultState,
                    "'" + std::string(name) + "': " + std::string(key) + " is one of " + values);
    }
    indices[static_cast<std::size_t>(p - type.properties.begin())] = v;
    start = comma + 1;
  }
  return static_cast<BlockId>(type.firstState + stateOffset(type, indices));
}

std::string BlockRegistry::stateName(BlockId state) const {
  const BlockType& type = (*this)[state];
  if (type.properties.empty()) return type.name;
  std::string name = type.name + "[";
  const std::vector<std::size_t> indices = valueIndicesOf(type, state - type.firstState);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (i > 0) name += ",";
    name += type.properties[i].name;
    name += "=";
    name += type.properties[i].values[indices[i]];
  }
  return name + "]";
}

StateValues BlockRegistry::stateValues(BlockId state) const {
  const BlockType& type = (*this)[state];
  StateValues values;
  const std::vector<std::size_t> indices = valueIndicesOf(type, state - type.firstState);
  for (std::size_t i = 0; i < indices.size(); ++i)
    values[type.properties[i].name] = type.properties[i].values[indices[i]];
  return values;
}

std::optional<BlockId> BlockRegistry::with(BlockId state, std::string_view property,
                                           std::string_view value) const {
  const BlockType& type = (*this)[state];
  const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                              [&](const BlockProperty& q) { return q.name == property; });
  if (p == type.properties.end()) return std::nullopt;
  const std::size_t v = valueIndex(*p, value);
  if (v == p->values.size()) return std::nullopt;
  std::vector<std::size_t> indices = valueIndicesOf(type, state - type.firstState);
  indices[static_cast<std::size_t>(p - type.properties.begin())] = v;
  return static_cast<BlockId>(type.firstState + stateOffset(type, indices));
}

}  // namespace terrasol
