#include "world/block_table.h"

#include <cmath>

#include "core/error.h"
#include "core/json_check.h"
#include "core/light_level.h"
#include "core/paths.h"
#include "world/block_json.h"

namespace terrasol {
namespace {

using namespace json_check;

// A box [x0, y0, z0, x1, y1, z1] in 1/16 (halves allowed), rounded outward to whole sixteenths. A
// box may reach beyond its cell (a fence's 24 high, a bell's overhang), never further than a cell.
ShapeBox parseBox(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != 6) expected(key, "[x0, y0, z0, x1, y1, z1]", value);
  ShapeBox box;
  for (std::size_t i = 0; i < 3; ++i) {
    const double from = numberIn(value[i], element(key, i), -kModelUnits, 2 * kModelUnits, false);
    const double to = numberIn(value[i + 3], element(key, i + 3), from, 2 * kModelUnits, false);
    box.from[i] = static_cast<int>(std::floor(from));
    box.to[i] = static_cast<int>(std::ceil(to));
  }
  return box;
}

std::vector<std::vector<ShapeBox>> parseShapes(const json& shapes) {
  if (!shapes.is_array() || shapes.size() < 2)
    expected("shapes", "an array of shapes, empty and full first", shapes);
  std::vector<std::vector<ShapeBox>> out(shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const std::string key = element("shapes", i);
    if (!shapes[i].is_array()) expected(key, "an array of boxes", shapes[i]);
    for (std::size_t b = 0; b < shapes[i].size(); ++b)
      out[i].push_back(parseBox(shapes[i][b], element(key, b)));
  }
  return out;
}

// A number for every state, or one list entry per state.
template <class T>
std::vector<T> perState(const json& value, const std::string& key, std::size_t states, std::int64_t hi) {
  if (!value.is_array()) return std::vector<T>(states, static_cast<T>(wholeNumber(value, key, 0, hi)));
  if (value.size() != states)
    expected(key, join({"a number or one per state (", std::to_string(states), ")"}), value);
  std::vector<T> out(states);
  for (std::size_t s = 0; s < states; ++s)
    out[s] = static_cast<T>(wholeNumber(value[s], element(key, s), 0, hi));
  return out;
}

TableBlock parseTableBlock(const json& block, const std::string& where, std::size_t shapeCount) {
  if (!block.is_object()) expected(where, "an object", block);
  TableBlock t;
  BlockType& type = t.type;
  type.name = nonEmptyString(required(block, where, "name"), member(where, "name"));
  const std::string at = join({where, " (", type.name, ")"});
  checkObject(block, at,
              {"name", "properties", "default", "opacity", "emission", "air", "transparent", "light_by_shape",
               "in_water", "collision", "hardness"});
  parseStates(block, type, at);
  type.minecraft = true;
  type.opacity = static_cast<std::uint8_t>(
      wholeNumber(required(block, at, "opacity"), member(at, "opacity"), 0, kMaxLight));
  t.emission = perState<std::uint8_t>(required(block, at, "emission"), member(at, "emission"),
                                      type.stateCount, kMaxLight);
  type.emission = t.emission[type.defaultState];
  const auto flag = [&](const char* name) {
    const json* v = field(block, name);
    return v && boolean(*v, member(at, name));
  };
  type.shapeOccludesLight = flag("light_by_shape");
  type.alwaysInWater = flag("in_water");
  if (!flag("air")) {
    type.shape = BlockShape::Model;
    type.layer = flag("transparent") ? RenderLayer::Cutout : RenderLayer::Opaque;
  }
  t.collision = perState<std::uint16_t>(required(block, at, "collision"), member(at, "collision"),
                                        type.stateCount, static_cast<std::int64_t>(shapeCount) - 1);
  type.hardness = parseHardness(required(block, at, "hardness"), member(at, "hardness"));
  return t;
}

}  // namespace

BlockTable BlockTable::fromJson(std::string_view text, const std::string& fileName) {
  const json root = parseJson(text, fileName);
  try {
    checkObject(root, "", {"source", "version", "shapes", "blocks"});
    BlockTable table;
    table.version = nonEmptyString(required(root, "", "version"), "version");
    table.shapes = parseShapes(required(root, "", "shapes"));
    const json& blocks = required(root, "", "blocks");
    if (!blocks.is_array() || blocks.empty()) expected("blocks", "a non-empty array, air first", blocks);
    table.blocks.reserve(blocks.size());
    for (std::size_t i = 0; i < blocks.size(); ++i)
      table.blocks.push_back(parseTableBlock(blocks[i], element("blocks", i), table.shapes.size()));
    return table;
  } catch (const Error& e) {
    throw Error(withFile(fileName, e.what()));
  }
}

BlockTable BlockTable::fromFile(const std::filesystem::path& file) {
  return fromJson(readTextFile(file), file.string());
}

std::filesystem::path BlockTable::shippedFile() {
  return dataRoot() / "data" / "minecraft_blocks.json";
}

}  // namespace terrasol
