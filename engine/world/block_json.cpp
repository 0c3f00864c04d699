#include "world/block_json.h"

#include <algorithm>

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
FaceTextures parseTextures(const json& textures, const std::string& key, bool partial = false) {
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
  for (std::size_t i = 0; i < faces.size() && !partial; ++i) {
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
    if (!value.is_string() || p->indexOf(value.get<std::string>()) == p->values.size()) {
      expected(member(key, name), "one of the property's values", value);
    }
    indices[static_cast<std::size_t>(p - type.properties.begin())] = p->indexOf(value.get<std::string>());
  }
  return type.stateOffset(indices);
}

// "none_when": "property=value", one of the block's own.
PropertyValue parseCondition(const json& value, const std::string& key, const BlockType& type) {
  const std::string text = nonEmptyString(value, key);
  const std::size_t eq = text.find('=');
  const auto p = std::find_if(type.properties.begin(), type.properties.end(),
                              [&](const BlockProperty& q) { return q.name == text.substr(0, eq); });
  if (eq == std::string::npos || p == type.properties.end() ||
      p->indexOf(text.substr(eq + 1)) == p->values.size()) {
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
  if (const json* list = field(block, "textures_when")) {
    const std::string key = member(at, "textures_when");
    if (type.shape == BlockShape::Model) fail(key, "a model block takes its textures from its models");
    if (!list->is_array()) expected(key, "an array of {\"when\", \"textures\"}", *list);
    for (std::size_t i = 0; i < list->size(); ++i) {
      const json& item = (*list)[i];
      const std::string k = element(key, i);
      if (!item.is_object()) expected(k, "an object", item);
      checkObject(item, k, {"when", "textures"});
      type.texturesWhen.push_back(
          {parseCondition(required(item, k, "when"), member(k, "when"), type),
           parseTextures(required(item, k, "textures"), member(k, "textures"), true)});
    }
  }
}

}  // namespace

void parseStates(const json& block, BlockType& type, const std::string& at) {
  parseProperties(block, type, at);
  type.defaultState = static_cast<BlockId>(defaultOffset(block, type, at));  // made absolute by the registry
}

float parseHardness(const json& value, const std::string& key) {
  if (value.is_number() && value.get<double>() == kUnbreakable) return kUnbreakable;
  return numberIn(value, key, 0.0, 1e6, false);
}

BlockType parsePackBlock(const json& block, const std::string& where) {
  if (!block.is_object()) expected(where, "an object", block);
  BlockType type;
  type.name = nonEmptyString(required(block, where, "name"), member(where, "name"));
  const std::string at = join({where, " (", type.name, ")"});
  checkObject(block, at,
              {"name", "shape", "layer", "textures", "tint", "opacity", "emission", "shape_occludes_light",
               "properties", "default", "placement", "wall_variant", "connects", "opens", "collision",
               "placeable", "textures_when", "hardness"});
  type.shape = BlockShape::Cube;
  type.inBlocksJson = true;
  parseLooks(block, type, at);
  type.opacity =
      static_cast<std::uint8_t>(parseLevel(block, "opacity", type.isOpaqueCube() ? kMaxLight : 0, at));
  type.emission = static_cast<std::uint8_t>(parseLevel(block, "emission", 0, at));
  if (const json* v = field(block, "shape_occludes_light")) {
    type.shapeOccludesLight = boolean(*v, member(at, "shape_occludes_light"));
  }
  parseStates(block, type, at);
  parseGameplay(block, type, at);
  if (const json* v = field(block, "placeable")) type.placeable = boolean(*v, member(at, "placeable"));
  if (const json* v = field(block, "hardness")) type.hardness = parseHardness(*v, member(at, "hardness"));
  return type;
}

void parseLooksAndRules(const json& block, BlockType& type, const std::string& where) {
  if (!block.is_object()) expected(where, "an object", block);
  const std::string at = join({where, " (", type.name, ")"});
  for (const char* fact :
       {"properties", "default", "opacity", "emission", "shape_occludes_light", "collision", "hardness"}) {
    if (field(block, fact)) fail(member(at, fact), "is Minecraft's, given by its block table: leave it out");
  }
  checkObject(block, at,
              {"name", "shape", "layer", "textures", "textures_when", "tint", "placement", "wall_variant",
               "connects", "opens"});
  type.shape = BlockShape::Cube;
  type.inBlocksJson = true;
  parseLooks(block, type, at);
  parseGameplay(block, type, at);
}

}  // namespace terrasol
