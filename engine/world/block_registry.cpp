#include "world/block_registry.h"

#include <algorithm>

#include "core/error.h"
#include "core/json_check.h"
#include "core/light_level.h"
#include "world/block_json.h"

namespace terrasol {

using namespace json_check;

BlockRegistry BlockRegistry::load(const BlockTable& table, std::string_view blocksJson,
                                  const std::string& fileName) {
  BlockRegistry registry;
  registry.shapes_ = table.shapes;
  for (const TableBlock& b : table.blocks) registry.add(b.type, b.emission, b.collision);
  registry.minecraftBlocks_ = registry.types_.size();
  const json root = parseJson(blocksJson, fileName);
  try {
    registry.overlay(root);
  } catch (const Error& e) {
    throw Error(withFile(fileName, e.what()));
  }
  registry.implyPlacements();
  registry.finish();
  registry.blocksBeforePacks_ = registry.types_.size();
  return registry;
}

namespace {

// Blocks Minecraft renamed, by their old names (its data fixers): a world saved before keeps them.
constexpr std::pair<std::string_view, std::string_view> kRenamedBlocks[] = {
    {"grass", "short_grass"},    // 1.20.3
    {"chain", "iron_chain"},     // 1.21.9
    {"grass_path", "dirt_path"}  // 1.17
};

const BlockProperty* propertyOf(const BlockType& type, std::string_view name) {
  for (const BlockProperty& p : type.properties)
    if (p.name == name) return &p;
  return nullptr;
}

bool hasValue(const BlockType& type, std::string_view name, std::string_view value) {
  const BlockProperty* p = propertyOf(type, name);
  return p && p->indexOf(value) < p->values.size();
}

// The name Minecraft gives now to a block it renamed; `name` itself otherwise.
std::string_view renamedBlock(std::string_view name) {
  for (const auto& [old, now] : kRenamedBlocks)
    if (old == name) return now;
  return name;
}

// The rule a Minecraft block's properties imply, as Minecraft places blocks with them.
PlacementRule impliedPlacement(const BlockType& type) {
  if (propertyOf(type, "hinge")) return PlacementRule::Door;
  if (hasValue(type, "part", "foot")) return PlacementRule::Bed;
  if (hasValue(type, "half", "upper")) return PlacementRule::TwoTall;
  if (hasValue(type, "face", "wall")) return PlacementRule::Attached;
  if (propertyOf(type, "rotation")) return PlacementRule::Rotation;
  if (hasValue(type, "shape", "ascending_north")) return PlacementRule::Rail;
  if (hasValue(type, "type", "double")) return PlacementRule::Slab;
  if (hasValue(type, "half", "top") && propertyOf(type, "shape")) return PlacementRule::Stairs;
  if (hasValue(type, "half", "top") && propertyOf(type, "open")) return PlacementRule::Trapdoor;
  if (hasValue(type, "axis", "y") && hasValue(type, "axis", "x")) return PlacementRule::Axis;
  if (hasValue(type, "facing", "down")) return PlacementRule::Pointing;
  if (propertyOf(type, "facing")) return PlacementRule::FacingBack;
  if (propertyOf(type, "layers")) return PlacementRule::Layers;
  return PlacementRule::None;
}

// Minecraft names a block's wall form by putting "wall_" before its kind: oak_sign, oak_wall_sign;
// skeleton_skull, skeleton_wall_skull; oak_hanging_sign, oak_wall_hanging_sign; tube_coral_fan,
// tube_coral_wall_fan; soul_torch, soul_wall_torch.
std::string wallFormOf(const std::string& name) {
  for (const char* kind : {"hanging_sign", "sign", "banner", "skull", "head", "fan", "torch"}) {
    const std::string k = kind;
    if (name.size() > k.size() && name.ends_with("_" + k))
      return name.substr(0, name.size() - k.size()) + "wall_" + k;
  }
  return "";
}

}  // namespace

void BlockRegistry::implyPlacements() {
  for (std::size_t i = 0; i < minecraftBlocks_; ++i) {
    BlockType& type = types_[i];
    if (type.placement != PlacementRule::None || type.shape == BlockShape::None) continue;
    type.placement = impliedPlacement(type);
    // A standing block with a wall form stands on floors and hangs on walls.
    const std::string wall = wallFormOf(type.name);
    const auto it = wall.empty() ? byName_.end() : byName_.find(wall);
    if (it == byName_.end() || type.wallVariant != kAir) continue;
    type.wallVariant = types_[it->second].defaultState;
    if (type.placement == PlacementRule::None) type.placement = PlacementRule::Torch;
    if (types_[it->second].placement == PlacementRule::None)
      types_[it->second].placement = PlacementRule::Wall;
  }
}

void BlockRegistry::addPackBlocks(std::vector<BlockType> types) {
  for (BlockType& type : types) {
    if (byName_.contains(type.name)) throw Error(join({"block \"", type.name, "\" is known already"}));
    add(std::move(type));
  }
  finish();
}

BlockRegistry BlockRegistry::load(const std::filesystem::path& blocksJson) {
  return load(BlockTable::fromFile(BlockTable::shippedFile()), readTextFile(blocksJson), blocksJson.string());
}

BlockRegistry BlockRegistry::fromJson(std::string_view text, const std::string& fileName) {
  return load(BlockTable{}, text, fileName);
}

void BlockRegistry::overlay(const json& root) {
  checkObject(root, "", {"blocks"});
  const json& blocks = required(root, "", "blocks");
  if (!blocks.is_array() || blocks.empty()) expected("blocks", "a non-empty array, air first", blocks);
  std::vector<std::size_t> typeOf(blocks.size());  // entry -> block index
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string where = element("blocks", i);
    const json* name = blocks[i].is_object() ? field(blocks[i], "name") : nullptr;
    const auto known = name && name->is_string() ? byName_.find(name->get<std::string>()) : byName_.end();
    if (known != byName_.end() && known->second < minecraftBlocks_) {
      parseLooksAndRules(blocks[i], types_[known->second], where);
      typeOf[i] = known->second;
    } else {
      typeOf[i] = types_.size();
      add(parsePackBlock(blocks[i], where));
    }
  }
  // "wall_variant" names a block, so it is resolved once all are read.
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    BlockType& type = types_[typeOf[i]];
    const std::string at = join({element("blocks", i), " (", type.name, ")"});
    const json* v = field(blocks[i], "wall_variant");
    if (!v && type.placement == PlacementRule::Torch) fail(at, "placement \"torch\" needs \"wall_variant\"");
    if (!v) continue;
    const auto it = byName_.find(nonEmptyString(*v, member(at, "wall_variant")));
    if (it == byName_.end()) expected(member(at, "wall_variant"), "the name of a block", *v);
    type.wallVariant = types_[it->second].defaultState;
  }
}

void BlockRegistry::add(BlockType type, const std::vector<std::uint8_t>& emission,
                        const std::vector<std::uint16_t>& collision) {
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
    emission_.push_back(emission.empty() ? type.emission : emission[s]);
    collision_.push_back(collision.empty() ? kNoShape : collision[s]);
  }
  types_.push_back(std::move(type));
}

void BlockRegistry::finish() {
  const auto water = byName_.find("water");
  const std::uint8_t waterOpacity = water == byName_.end() ? 0 : types_[water->second].opacity;
  if (water != byName_.end()) waterState_ = types_[water->second].defaultState;
  opacity_.resize(size());
  opaqueCube_.resize(size());
  water_.resize(size());
  for (const BlockType& type : types_) {
    const auto logged = std::find_if(type.properties.begin(), type.properties.end(),
                                     [](const BlockProperty& p) { return p.name == "waterlogged"; });
    for (std::uint16_t s = 0; s < type.stateCount; ++s) {
      const std::size_t state = type.firstState + s;
      const bool inWater =
          type.alwaysInWater ||
          (logged != type.properties.end() &&
           logged->values[type.valueIndices(s)[static_cast<std::size_t>(logged - type.properties.begin())]] ==
               "true");
      water_[state] = inWater ? 1 : 0;
      opacity_[state] = inWater ? std::max(type.opacity, waterOpacity) : type.opacity;
      opaqueCube_[state] = type.isOpaqueCube() ? 1 : 0;
    }
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
  auto it = byName_.find(blockName);
  if (it == byName_.end()) it = byName_.find(std::string(renamedBlock(blockName)));
  if (it == byName_.end()) return report(kAir, join({"unknown block '", blockName, "'"}));
  const BlockType& type = types_[it->second];
  if (found) *found = true;
  if (open == std::string_view::npos) return type.defaultState;
  if (name.back() != ']') return report(type.defaultState, join({"'", name, "': expected ']' at the end"}));
  std::vector<std::size_t> indices = type.valueIndices(type.defaultState - type.firstState);
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
    const std::size_t v = p->indexOf(value);
    if (v == p->values.size()) {
      std::string values;
      for (const std::string& s : p->values) values += join({values.empty() ? "" : ", ", s});
      return report(type.defaultState, join({"'", name, "': ", key, " is one of ", values}));
    }
    indices[static_cast<std::size_t>(p - type.properties.begin())] = v;
    start = comma + 1;
  }
  return static_cast<BlockId>(type.firstState + type.stateOffset(indices));
}

std::string BlockRegistry::stateName(BlockId state) const {
  const BlockType& type = (*this)[state];
  if (type.properties.empty()) return type.name;
  std::string name = type.name + "[";
  const std::vector<std::size_t> indices = type.valueIndices(state - type.firstState);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (i > 0) name += ",";
    name += type.properties[i].name;
    name += "=";
    name += type.properties[i].values[indices[i]];
  }
  return name + "]";
}

FaceTextures BlockRegistry::faceTextures(BlockId state) const {
  const BlockType& type = (*this)[state];
  FaceTextures faces = type.textures;
  if (type.texturesWhen.empty()) return faces;
  const StateValues values = stateValues(state);
  for (const BlockType::TexturesWhen& w : type.texturesWhen) {
    const auto v = values.find(w.when.property);
    if (v == values.end() || v->second != w.when.value) continue;
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (!w.textures[f].empty()) faces[f] = w.textures[f];
  }
  return faces;
}

StateValues BlockRegistry::stateValues(BlockId state) const {
  const BlockType& type = (*this)[state];
  StateValues values;
  const std::vector<std::size_t> indices = type.valueIndices(state - type.firstState);
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
  const std::size_t v = p->indexOf(value);
  if (v == p->values.size()) return std::nullopt;
  std::vector<std::size_t> indices = type.valueIndices(state - type.firstState);
  indices[static_cast<std::size_t>(p - type.properties.begin())] = v;
  return static_cast<BlockId>(type.firstState + type.stateOffset(indices));
}

}  // namespace terrasol
