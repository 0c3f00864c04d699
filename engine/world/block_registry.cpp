#include "world/block_registry.h"

#include <algorithm>

#include "core/error.h"
#include "core/json_check.h"
#include "core/light_level.h"

namespace terrasol {
namespace {

using namespace json_check;

constexpr EnumNames<BlockShape, 6> kShapes{{"none", "cube", "cross", "liquid", "torch", "model"}};
constexpr EnumNames<RenderLayer, 4> kLayers{{"", "opaque", "cutout", "translucent"}};  // None: shape none's
constexpr EnumNames<Tint, kTintCount> kTints{{"none", "grass", "foliage", "water", "birch", "spruce"}};

std::vector<std::string> textureCandidates(const json& value, const std::string& key) {
  if (value.is_string()) return {value.get<std::string>()};
  if (!value.is_array() || value.empty()) expected(key, "a texture name or a non-empty list of names", value);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!value[i].is_string()) expected(element(key, i), "a texture name", value[i]);
    names.push_back(value[i].get<std::string>());
  }
  return names;
}

// "all", then "side"/"end", then "top"/"bottom", then single faces: later keys refine earlier ones.
FaceTextures parseTextures(const json& textures, const std::string& key) {
  checkObject(textures, key,
              {"all", "side", "end", "top", "bottom", "west", "east", "down", "up", "north", "south"});
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
  FaceTextures faces;
  for (const auto& [name, indices] : kKeys) {
    const json* value = field(textures, name);
    if (!value) continue;
    const auto names = textureCandidates(*value, member(key, name));
    for (int i : indices) faces[static_cast<std::size_t>(i)] = names;
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (faces[i].empty()) fail(key, "leaves a face without a texture (give \"all\" or every face)");
  }
  return faces;
}

int parseLevel(const json& block, const char* name, int fallback, const std::string& at) {
  const json* value = field(block, name);
  return value ? static_cast<int>(wholeNumber(*value, member(at, name), 0, kMaxLight)) : fallback;
}

// Property names and values go into state names ("oak_log[axis=x]") unquoted.
void checkStateWord(const std::string& word, const std::string& key) {
  if (word.find_first_of("[],=") != std::string::npos) {
    fail(key, join({"\"", word, "\": names and values may not contain '[', ']', ',' or '='"}));
  }
}

// "properties": {"axis": ["y", "x", "z"]} and "default": {"axis": "y"}: the block's states.
void parseProperties(const json& block, BlockType& type, const std::string& at) {
  const json* props = field(block, "properties");
  if (!props) {
    if (field(block, "default")) fail(member(at, "default"), "needs \"properties\"");
    return;
  }
  const std::string key = member(at, "properties");
  if (!props->is_object() || props->empty()) expected(key, "a non-empty object", *props);
  std::size_t states = 1;
  for (const auto& [name, values] : props->items()) {
    const std::string k = member(key, name);
    if (!values.is_array() || values.empty()) expected(k, "a non-empty array of values", values);
    checkStateWord(name, k);
    BlockProperty p{name, {}};
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::string value = nonEmptyString(values[i], element(k, i));
      checkStateWord(value, element(k, i));
      if (std::find(p.values.begin(), p.values.end(), value) != p.values.end()) {
        fail(element(k, i), join({"lists \"", value, "\" twice"}));
      }
      p.values.push_back(value);
    }
    states *= p.values.size();
    if (states > 4096) fail(key, "make more than 4096 states");
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
std::size_t defaultOffset(const json& block, const BlockType& type, const std::string& at) {
  std::vector<std::size_t> indices(type.properties.size(), 0);
  const json* d = field(block, "default");
  if (!d) return 0;
  const std::string key = member(at, "default");
  if (!d->is_object()) expected(key, "an object", *d);
  for (const auto& [name, value] : d->items()) {
    const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                                [&](const BlockProperty& q) { return q.name == name; });
    if (p == type.properties.end()) fail(member(key, name), "is not one of its properties");
    if (!value.is_string() || valueIndex(*p, value.get<std::string>()) == p->values.size()) {
      expected(member(key, name), "one of the property's values", value);
    }
    indices[static_cast<std::size_t>(p - type.properties.begin())] = valueIndex(*p, value.get<std::string>());
  }
  return stateOffset(type, indices);
}

// "none_when": "property=value", one of the block's own.
PropertyValue parseCondition(const json& value, const std::string& key, const BlockType& type) {
  const std::string text = nonEmptyString(value, key);
  const std::size_t eq = text.find('=');
  const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                              [&](const BlockProperty& q) { return q.name == text.substr(0, eq); });
  if (eq == std::string::npos || p == type.properties.end() ||
      valueIndex(*p, text.substr(eq + 1)) == p->values.size()) {
    expected(key, "one of its property=value pairs", value);
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

// The rules the game follows; "wall_variant" names a block, resolved once all are read.
void parseGameplay(const json& block, BlockType& type, const std::string& at) {
  if (const json* v = field(block, "placement")) {
    type.placement = enumOf(*v, member(at, "placement"), kPlacementRules);
  }
  if (const json* v = field(block, "connects")) type.connects = enumOf(*v, member(at, "connects"), kConnects);
  if (const json* v = field(block, "opens")) type.opens = boolean(*v, member(at, "opens"));
  const json* collision = field(block, "collision");
  if (!collision) return;
  const std::string key = member(at, "collision");
  checkObject(*collision, key, {"height", "none_when"});
  if (const json* h = field(*collision, "height")) {
    type.collisionHeight = static_cast<std::uint8_t>(wholeNumber(*h, member(key, "height"), 1, 32));
  }
  if (const json* w = field(*collision, "none_when")) {
    type.passableWhen = parseCondition(*w, member(key, "none_when"), type);
  }
}

// How it looks: shape, layer and textures.
void parseLooks(const json& block, BlockType& type, const std::string& at) {
  if (const json* v = field(block, "shape")) type.shape = enumOf(*v, member(at, "shape"), kShapes);
  if (const json* v = field(block, "tint")) type.tint = enumOf(*v, member(at, "tint"), kTints);
  if (type.shape == BlockShape::None) return;
  const bool solid = type.shape == BlockShape::Cube || type.shape == BlockShape::Model;
  type.layer = solid ? RenderLayer::Opaque : RenderLayer::Cutout;
  if (const json* v = field(block, "layer")) type.layer = enumOf(*v, member(at, "layer"), kLayers);
  // A model block's textures come from its models (assets/minecraft/blockstates/<name>.json).
  if (type.shape != BlockShape::Model) {
    type.textures = parseTextures(required(block, at, "textures"), member(at, "textures"));
  } else if (field(block, "textures")) {
    fail(member(at, "textures"), "a model block takes its textures from its models");
  }
}

// `at` names the block by index and name: "blocks[3] (oak_log)".
BlockType parseBlock(const json& block, const std::string& where) {
  if (!block.is_object()) expected(where, "an object", block);
  BlockType type;
  type.name = nonEmptyString(required(block, where, "name"), member(where, "name"));
  const std::string at = join({where, " (", type.name, ")"});
  checkObject(block, at,
              {"name", "shape", "layer", "textures", "tint", "opacity", "emission", "shape_occludes_light",
               "properties", "default", "placement", "wall_variant", "connects", "opens", "collision"});
  type.shape = BlockShape::Cube;
  parseLooks(block, type, at);
  type.opacity =
      static_cast<std::uint8_t>(parseLevel(block, "opacity", type.isOpaqueCube() ? kMaxLight : 0, at));
  type.emission = static_cast<std::uint8_t>(parseLevel(block, "emission", 0, at));
  if (const json* v = field(block, "shape_occludes_light")) {
    type.shapeOccludesLight = boolean(*v, member(at, "shape_occludes_light"));
  }
  parseProperties(block, type, at);
  parseGameplay(block, type, at);
  type.defaultState = static_cast<BlockId>(defaultOffset(block, type, at));  // made absolute by the registry
  return type;
}

}  // namespace

BlockRegistry BlockRegistry::fromFile(const std::filesystem::path& file) {
  return fromJson(readTextFile(file), file.string());
}

BlockRegistry BlockRegistry::fromJson(std::string_view text, const std::string& fileName) {
  const json root = parseJson(text, fileName);
  try {
    checkObject(root, "", {"blocks"});
    const json& blocks = required(root, "", "blocks");
    if (!blocks.is_array() || blocks.empty()) expected("blocks", "a non-empty array, air first", blocks);
    BlockRegistry registry;
    for (std::size_t i = 0; i < blocks.size(); ++i) registry.add(parseBlock(blocks[i], element("blocks", i)));
    // "wall_variant" names a block, so it is resolved once all are read.
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      BlockType& type = registry.types_[i];
      const std::string at = join({element("blocks", i), " (", type.name, ")"});
      const json* v = field(blocks[i], "wall_variant");
      if (!v && type.placement == PlacementRule::Torch) {
        fail(at, "placement \"torch\" needs \"wall_variant\"");
      }
      if (!v) continue;
      const auto it = registry.byName_.find(nonEmptyString(*v, member(at, "wall_variant")));
      if (it == registry.byName_.end()) expected(member(at, "wall_variant"), "the name of a block", *v);
      type.wallVariant = registry.types_[it->second].defaultState;
    }
    return registry;
  } catch (const Error& e) {
    throw Error(withFile(fileName, e.what()));
  }
}

void BlockRegistry::add(BlockType type) {
  const std::size_t i = types_.size();
  if (i == 0 && (type.name != "air" || type.shape != BlockShape::None || type.stateCount != 1)) {
    fail("blocks[0]", "must be \"air\" with shape \"none\" and no properties");
  }
  if (blockOf_.size() + type.stateCount > 65535) fail("blocks", "more than 65535 block states");
  if (!byName_.emplace(type.name, static_cast<BlockId>(i)).second) {
    fail(member(element("blocks", i), "name"), join({"duplicate block name \"", type.name, "\""}));
  }
  type.firstState = static_cast<BlockId>(blockOf_.size());
  type.defaultState = static_cast<BlockId>(type.firstState + type.defaultState);
  for (std::uint16_t s = 0; s < type.stateCount; ++s) {
    blockOf_.push_back(static_cast<std::uint16_t>(i));
    opacity_.push_back(type.opacity);
    emission_.push_back(type.emission);
    opaqueCube_.push_back(type.isOpaqueCube() ? 1 : 0);
  }
  types_.push_back(std::move(type));
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
  if (it == byName_.end()) return report(kAir, join({"unknown block '", blockName, "'"}));
  const BlockType& type = types_[it->second];
  if (found) *found = true;
  if (open == std::string_view::npos) return type.defaultState;
  if (name.back() != ']') return report(type.defaultState, join({"'", name, "': expected ']' at the end"}));
  std::vector<std::size_t> indices = valueIndicesOf(type, type.defaultState - type.firstState);
  const std::string_view list = name.substr(open + 1, name.size() - open - 2);
  std::size_t start = 0;
  while (start <= list.size() && !list.empty()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view pair = list.substr(start, comma - start);
    const std::size_t eq = pair.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == pair.size()) {
      return report(type.defaultState, join({"'", name, "': expected property=value, not '", pair, "'"}));
    }
    const std::string_view key = pair.substr(0, eq), value = pair.substr(eq + 1);
    const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                                [&](const BlockProperty& q) { return q.name == key; });
    if (p == type.properties.end()) {
      return report(type.defaultState, join({"'", name, "': ", type.name, " has no property '", key, "'"}));
    }
    const std::size_t v = valueIndex(*p, value);
    if (v == p->values.size()) {
      std::string values;
      for (const std::string& s : p->values) values += join({values.empty() ? "" : ", ", s});
      return report(type.defaultState, join({"'", name, "': ", key, " is one of ", values}));
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
