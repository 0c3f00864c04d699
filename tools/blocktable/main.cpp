// terrasol-blocktable: converts Minecraft's block facts (PrismarineJS minecraft-data, MIT) into
// Terrasol's own block table, data/minecraft_blocks.json (format: docs/world.md, "Blocks").
//   terrasol-blocktable MINECRAFT_DATA_VERSION_DIR [OUT]
// e.g. terrasol-blocktable minecraft-data/data/pc/1.21.11 data/minecraft_blocks.json
// (MINECRAFT_DATA_VERSION_DIR holds minecraft-data's blocks.json and blockCollisionShapes.json)
//
// The upstream files give each block's light as its default state's; the rules below give it per
// state as Minecraft computes it, and are checked against the upstream value at the default state.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/tool_main.h"

namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using terrasol::Error;
using Values = std::map<std::string, std::string>;

json readJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read " + file.string());
  return json::parse(in);
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

int number(const Values& v, const char* property) {
  return std::stoi(v.at(property));
}

// The light a state emits, where Minecraft varies it by state (BlockBehaviour.Properties.lightLevel
// of each block); nothing where the block's one value holds for every state.
std::optional<int> emissionByState(const std::string& name, const Values& v) {
  if (v.count("lit")) {
    if (v.at("lit") == "false") return 0;
    if (name == "furnace" || name == "smoker" || name == "blast_furnace") return 13;
    if (endsWith(name, "redstone_ore")) return 9;
    if (name == "redstone_torch" || name == "redstone_wall_torch") return 7;
    if (name == "redstone_lamp" || name == "campfire") return 15;
    if (name == "soul_campfire") return 10;
    if (endsWith(name, "candle")) return 3 * number(v, "candles");
    if (endsWith(name, "candle_cake")) return 3;
    if (endsWith(name, "copper_bulb")) {  // dimmer as the copper weathers
      if (name.find("exposed") != std::string::npos) return 12;
      if (name.find("weathered") != std::string::npos) return 8;
      if (name.find("oxidized") != std::string::npos) return 4;
      return 15;
    }
    throw Error(name + " has \"lit\" and no light rule");
  }
  if (name == "sea_pickle") return v.at("waterlogged") == "true" ? 3 + 3 * number(v, "pickles") : 0;
  if (name == "light") return number(v, "level");
  if (name == "respawn_anchor") return static_cast<int>(std::floor(number(v, "charges") / 4.0 * 15.0));
  if (name == "cave_vines" || name == "cave_vines_plant") return v.at("berries") == "true" ? 14 : 0;
  if (name == "glow_lichen") {
    for (const char* face : {"down", "up", "north", "south", "west", "east"})
      if (v.at(face) == "true") return 7;
    return 0;
  }
  if (name == "vault") return v.at("vault_state") == "inactive" ? 6 : 12;
  if (name == "trial_spawner") {
    const std::string& s = v.at("trial_spawner_state");
    if (s == "waiting_for_players") return 4;
    if (s == "inactive" || s == "cooldown") return 0;
    return 8;  // active, waiting_for_reward_ejection, ejecting_reward
  }
  return std::nullopt;
}

// Blocks whose light passes by their shape (Minecraft's useShapeForLightOcclusion): a bottom slab
// lets sky light in through its open top half.
bool lightByShape(const std::string& name) {
  static const std::set<std::string> kNamed = {
      "snow",        "farmland",         "dirt_path",         "lectern",
      "stonecutter", "enchanting_table", "daylight_detector", "end_portal_frame"};
  return endsWith(name, "_slab") || endsWith(name, "_stairs") || kNamed.count(name) > 0;
}

// Minecraft's air blocks (its AirBlock): nothing drawn, nothing in the way.
bool isAir(const std::string& name) {
  return name == "air" || name == "cave_air" || name == "void_air";
}

// Blocks that always stand in water, without a "waterlogged" property.
bool alwaysInWater(const std::string& name) {
  static const std::set<std::string> kNamed = {"seagrass", "tall_seagrass", "kelp", "kelp_plant",
                                               "bubble_column"};
  return kNamed.count(name) > 0;
}

struct Property {
  std::string name;
  std::vector<std::string> values;
};

// A block's properties as the table lists them: bool values "true" first, as Minecraft numbers them.
std::vector<Property> propertiesOf(const json& block) {
  std::vector<Property> props;
  for (const json& s : block.at("states")) {
    Property p{s.at("name").get<std::string>(), {}};
    if (s.at("type") == "bool") {
      p.values = {"true", "false"};
    } else {
      for (const json& v : s.at("values")) p.values.push_back(v.get<std::string>());
    }
    if (p.values.size() != s.at("num_values").get<std::size_t>()) throw Error(p.name + ": value count");
    if (!props.empty() && !(props.back().name < p.name)) throw Error("properties not sorted by name");
    props.push_back(std::move(p));
  }
  return props;
}

// The values of the state `offset` states after the block's first; the last property counts fastest.
Values valuesOf(const std::vector<Property>& props, std::size_t offset) {
  Values v;
  for (std::size_t i = props.size(); i-- > 0;) {
    v[props[i].name] = props[i].values[offset % props[i].values.size()];
    offset /= props[i].values.size();
  }
  return v;
}

// A shape's boxes in 1/16 of a block (halves where Minecraft has them: chains, bamboo).
ordered_json boxesInSixteenths(const json& boxes) {
  ordered_json out = ordered_json::array();
  for (const json& box : boxes) {
    ordered_json b = ordered_json::array();
    for (const json& c : box) {
      const double sixteenths = c.get<double>() * 16.0;
      const double half = std::round(sixteenths * 2.0) / 2.0;
      if (std::abs(half - sixteenths) > 1e-6) throw Error("a collision box off the 1/32 grid");
      if (half == std::floor(half)) {
        b.push_back(static_cast<int>(half));
      } else {
        b.push_back(half);
      }
    }
    out.push_back(b);
  }
  return out;
}

struct Table {
  std::vector<std::string> lines;   // one block each
  std::map<int, int> shapeIndex;    // upstream shape id -> index in `shapes`
  std::vector<std::string> shapes;  // one line each
};

int shapeOf(Table& table, const json& upstreamShapes, int id) {
  const auto [it, added] = table.shapeIndex.emplace(id, static_cast<int>(table.shapes.size()));
  if (added) table.shapes.push_back(boxesInSixteenths(upstreamShapes.at(std::to_string(id))).dump());
  return it->second;
}

ordered_json convertBlock(const json& block, const json& collision, const json& upstreamShapes, Table& table,
                          std::size_t expectedFirst) {
  const std::string name = block.at("name");
  const auto props = propertiesOf(block);
  const std::size_t first = block.at("minStateId"), last = block.at("maxStateId");
  std::size_t count = 1;
  for (const Property& p : props) count *= p.values.size();
  if (first != expectedFirst || last + 1 - first != count) throw Error(name + ": state ids not contiguous");

  ordered_json out;
  out["name"] = name;
  if (!props.empty()) {
    ordered_json p = ordered_json::object();
    for (const Property& q : props) p[q.name] = q.values;
    out["properties"] = p;
    const Values defaults = valuesOf(props, block.at("defaultState").get<std::size_t>() - first);
    ordered_json d = ordered_json::object();
    for (const Property& q : props)
      if (defaults.at(q.name) != q.values.front()) d[q.name] = defaults.at(q.name);
    if (!d.empty()) out["default"] = d;
  }
  out["opacity"] = block.at("filterLight");
  out["hardness"] = block.at("hardness");

  const int upstreamEmission = block.at("emitLight");
  const std::size_t defaultOffset = block.at("defaultState").get<std::size_t>() - first;
  std::vector<int> emission(count, upstreamEmission);
  bool varies = false;
  for (std::size_t s = 0; s < count; ++s) {
    if (const auto e = emissionByState(name, valuesOf(props, s))) {
      emission[s] = *e;
      varies = varies || *e != emission[0];
      if (s == defaultOffset && *e != upstreamEmission)
        throw Error(name + ": light rule disagrees at its default");
    }
  }
  out["emission"] = varies ? json(emission) : json(emission[0]);
  if (isAir(name)) out["air"] = true;
  if (block.at("transparent").get<bool>()) out["transparent"] = true;
  if (lightByShape(name)) out["light_by_shape"] = true;
  if (alwaysInWater(name)) out["in_water"] = true;

  if (collision.is_number()) {
    out["collision"] = shapeOf(table, upstreamShapes, collision.get<int>());
  } else {
    if (collision.size() != count) throw Error(name + ": collision list length");
    std::vector<int> perState;
    for (const json& id : collision) perState.push_back(shapeOf(table, upstreamShapes, id.get<int>()));
    out["collision"] = perState;
  }
  return out;
}

void write(const Table& table, const std::filesystem::path& file, const std::string& version) {
  std::ofstream out(file);
  out << "{\n  \"source\": \"PrismarineJS/minecraft-data, data/pc/" << version
      << " (MIT); written by terrasol-blocktable\",\n";
  out << "  \"version\": \"" << version << "\",\n  \"shapes\": [\n";
  for (std::size_t i = 0; i < table.shapes.size(); ++i)
    out << "    " << table.shapes[i] << (i + 1 < table.shapes.size() ? ",\n" : "\n");
  out << "  ],\n  \"blocks\": [\n";
  for (std::size_t i = 0; i < table.lines.size(); ++i)
    out << "    " << table.lines[i] << (i + 1 < table.lines.size() ? ",\n" : "\n");
  out << "  ]\n}\n";
  if (!out) throw Error("cannot write " + file.string());
}

}  // namespace

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-blocktable", [&] {
    if (argc < 2) throw Error("usage: terrasol-blocktable MINECRAFT_DATA_VERSION_DIR [OUT]");
    const std::filesystem::path dir = argv[1];
    const std::filesystem::path outFile = argc > 2 ? argv[2] : "minecraft_blocks.json";
    const json blocks = readJson(dir / "blocks.json");
    const json shapes = readJson(dir / "blockCollisionShapes.json");
    Table table;
    shapeOf(table, shapes.at("shapes"), 0);  // 0: empty, 1: the whole cell, as upstream
    shapeOf(table, shapes.at("shapes"), 1);
    std::size_t nextState = 0;
    for (const json& block : blocks) {
      const ordered_json row =
          convertBlock(block, shapes.at("blocks").at(block.at("name").get<std::string>()),
                       shapes.at("shapes"), table, nextState);
      nextState = block.at("maxStateId").get<std::size_t>() + 1;
      table.lines.push_back(row.dump());
    }
    write(table, outFile, dir.filename().string());
    std::printf("wrote %zu blocks, %zu states, %zu shapes to %s\n", table.lines.size(), nextState,
                table.shapes.size(), outFile.string().c_str());
    return 0;
  });
}
