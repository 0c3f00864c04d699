// The default pack's block families beyond the shaped materials: the woods' bark blocks, carpets and
// glass panes in every colour, the newer woods' logs, fences, gates, doors and trapdoors (oak's files
// renamed), pressure plates and columns, in Minecraft's layout on Minecraft's templates.

#include <array>
#include <filesystem>

#include "block_files.h"
#include "core/error.h"
#include "core/paths.h"
#include "recipes.h"

namespace terrasol::packgen {
namespace {

// The woods whose logs the pack has: their bark blocks ("oak_wood", "stripped_oak_wood") are the log's
// side all round, standing along their axis as logs do.
constexpr const char* kWoods[] = {"oak",    "birch",  "spruce",   "acacia",  "dark_oak",
                                  "jungle", "cherry", "mangrove", "pale_oak"};

// The newer woods' logs, fences, gates, doors and trapdoors are oak's files renamed: the same models on
// their own textures (families.cpp paints them).
constexpr const char* kOakLikeWoods[] = {"jungle", "cherry", "mangrove", "pale_oak"};
// Woods without logs here (the Nether's stems, bamboo): their fences, gates, doors and trapdoors.
constexpr const char* kOakLikeCrafts[] = {"crimson", "warped", "bamboo"};
constexpr const char* kOakFiles[] = {"blockstates/oak_log",
                                     "blockstates/stripped_oak_log",
                                     "blockstates/oak_fence",
                                     "blockstates/oak_fence_gate",
                                     "blockstates/oak_door",
                                     "blockstates/oak_trapdoor",
                                     "models/block/oak_log",
                                     "models/block/stripped_oak_log",
                                     "models/block/oak_fence_post",
                                     "models/block/oak_fence_side",
                                     "models/block/oak_fence_gate",
                                     "models/block/oak_fence_gate_open",
                                     "models/block/oak_door_bottom_left",
                                     "models/block/oak_door_bottom_right",
                                     "models/block/oak_door_top_left",
                                     "models/block/oak_door_top_right",
                                     "models/block/oak_trapdoor_bottom",
                                     "models/block/oak_trapdoor_open",
                                     "models/block/oak_trapdoor_top"};

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

void addOakLike(const std::string& wood, bool logs, std::vector<GeneratedFile>& out) {
  const std::filesystem::path pack = resourcePackDir() / "default" / "assets" / "minecraft";
  for (const char* oak : kOakFiles) {
    if (!logs && std::string(oak).find("_log") != std::string::npos) continue;
    const std::string text = readTextFile(pack / (std::string(oak) + ".json"));
    out.push_back({"assets/minecraft/" + replaceAll(oak, "oak_", wood + "_") + ".json",
                   replaceAll(text, "oak_", wood + "_")});
  }
}

std::vector<std::string> woodBlocks() {
  std::vector<std::string> names;
  for (const char* wood : kWoods) {
    names.push_back(std::string(wood) + "_wood");
    names.push_back("stripped_" + std::string(wood) + "_wood");
  }
  return names;
}

void addWood(const std::string& name, std::vector<GeneratedFile>& out) {
  const std::string log = name.substr(0, name.size() - std::string("_wood").size()) + "_log";
  out.push_back(
      file("model", name,
           Json{{"parent", "block/cube_column"}, {"textures", {{"end", block(log)}, {"side", block(log)}}}}));
  Json variants;
  variants["axis=x"] = Json{{"model", block(name)}, {"x", 90}, {"y", 90}};
  variants["axis=y"] = Json{{"model", block(name)}};
  variants["axis=z"] = Json{{"model", block(name)}, {"x", 90}};
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// A carpet of each colour: Minecraft's carpet template with its wool.
std::vector<std::string> carpets() {
  std::vector<std::string> names;
  for (const auto& [colour, rgb] : kDyes) names.push_back(std::string(colour) + "_carpet");
  return names;
}

void addCarpet(const std::string& name, std::vector<GeneratedFile>& out) {
  const std::string wool = name.substr(0, name.size() - std::string("_carpet").size()) + "_wool";
  out.push_back(file("model", name, Json{{"parent", "block/carpet"}, {"textures", {{"wool", block(wool)}}}}));
  out.push_back(file("blockstates", name, Json{{"variants", {{"", {{"model", block(name)}}}}}}));
}

// Glass panes, clear and in each colour: a post, and a side or its absence toward each neighbour, as
// Minecraft's glass_pane is put together.
std::vector<std::string> panes() {
  std::vector<std::string> names{"glass_pane"};
  for (const auto& [colour, rgb] : kDyes) names.push_back(std::string(colour) + "_stained_glass_pane");
  return names;
}

}  // namespace

void addPane(const std::string& name, const std::string& pane, const std::string& edge,
             std::vector<GeneratedFile>& out) {
  for (const char* part : {"post", "side", "side_alt", "noside", "noside_alt"}) {
    out.push_back(file("model", name + "_" + part,
                       Json{{"parent", block(std::string("template_glass_pane_") + part)},
                            {"textures", {{"pane", block(pane)}, {"edge", block(edge)}}}}));
  }
  const auto part = [&](const char* side, const char* value, const std::string& model, int y) {
    Json apply{{"model", block(name + "_" + model)}};
    if (y != 0) apply["y"] = y;
    return Json{{"when", {{side, value}}}, {"apply", apply}};
  };
  Json parts = Json::array();
  parts.push_back(Json{{"apply", {{"model", block(name + "_post")}}}});
  parts.push_back(part("north", "true", "side", 0));
  parts.push_back(part("east", "true", "side", 90));
  parts.push_back(part("south", "true", "side_alt", 0));
  parts.push_back(part("west", "true", "side_alt", 90));
  parts.push_back(part("north", "false", "noside", 0));
  parts.push_back(part("east", "false", "noside_alt", 0));
  parts.push_back(part("south", "false", "noside_alt", 90));
  parts.push_back(part("west", "false", "noside", 270));
  out.push_back(file("blockstates", name, Json{{"multipart", parts}}));
}

namespace {

// Minecraft's pressure-plate templates: a plate a sixteenth high (half that pressed) inset by one on
// each side, its rim showing the texture's bottom row.
Json plateTemplate(double height) {
  const auto face = [](std::array<double, 4> uv, const char* cullface) {
    Json f{{"uv", {number(uv[0]), number(uv[1]), number(uv[2]), number(uv[3])}}, {"texture", "#texture"}};
    if (cullface) f["cullface"] = cullface;
    return f;
  };
  const double rim = 16.0 - height;
  Json faces;
  faces["down"] = face({1, 1, 15, 15}, "down");
  faces["up"] = face({1, 1, 15, 15}, nullptr);
  for (const char* side : {"north", "south", "west", "east"}) faces[side] = face({1, rim, 15, 16}, nullptr);
  Json element{{"from", {1, 0, 1}}, {"to", {15, number(height), 15}}, {"faces", faces}};
  return Json{{"parent", "block/block"}, {"textures", {{"particle", "#texture"}}}, {"elements", {element}}};
}

// Pressure plates and what they are made of; weighted plates go down with any power.
constexpr std::array<std::pair<const char*, const char*>, 16> kPlates = {
    {{"oak", "oak_planks"},
     {"spruce", "spruce_planks"},
     {"birch", "birch_planks"},
     {"jungle", "jungle_planks"},
     {"acacia", "acacia_planks"},
     {"cherry", "cherry_planks"},
     {"dark_oak", "dark_oak_planks"},
     {"pale_oak", "pale_oak_planks"},
     {"mangrove", "mangrove_planks"},
     {"bamboo", "bamboo_planks"},
     {"crimson", "crimson_planks"},
     {"warped", "warped_planks"},
     {"stone", "stone"},
     {"polished_blackstone", "polished_blackstone"},
     {"light_weighted", "gold_block"},
     {"heavy_weighted", "iron_block"}}};

void addPlates(std::vector<GeneratedFile>& out) {
  out.push_back(file("model", "pressure_plate_up", plateTemplate(1.0)));
  out.push_back(file("model", "pressure_plate_down", plateTemplate(0.5)));
  for (const auto& [material, texture] : kPlates) {
    const std::string name = std::string(material) + "_pressure_plate";
    for (const char* pose : {"", "_down"}) {
      out.push_back(file("model", name + pose,
                         Json{{"parent", block(std::string("pressure_plate_") + (*pose ? "down" : "up"))},
                              {"textures", {{"texture", block(texture)}}}}));
    }
    Json variants;
    if (std::string(material).ends_with("weighted")) {
      for (int power = 0; power <= 15; ++power)
        variants["power=" + std::to_string(power)] =
            Json{{"model", block(name + (power > 0 ? "_down" : ""))}};
    } else {
      variants["powered=false"] = Json{{"model", block(name)}};
      variants["powered=true"] = Json{{"model", block(name + "_down")}};
    }
    out.push_back(file("blockstates", name, Json{{"variants", variants}}));
  }
}

// Blocks standing along their axis like logs: a side texture round, an end texture on top and bottom
// (hyphae: the stem's side all round, as wood is).
struct Column {
  const char* name;
  const char* side;
  const char* end;
};
constexpr Column kColumns[] = {
    {"bone_block", "bone_block_side", "bone_block_top"},
    {"hay_block", "hay_block_side", "hay_block_top"},
    {"quartz_pillar", "quartz_pillar", "quartz_pillar_top"},
    {"purpur_pillar", "purpur_pillar", "purpur_pillar_top"},
    {"basalt", "basalt_side", "basalt_top"},
    {"polished_basalt", "polished_basalt_side", "polished_basalt_top"},
    {"crimson_stem", "crimson_stem", "crimson_stem_top"},
    {"stripped_crimson_stem", "stripped_crimson_stem", "stripped_crimson_stem_top"},
    {"crimson_hyphae", "crimson_stem", "crimson_stem"},
    {"stripped_crimson_hyphae", "stripped_crimson_stem", "stripped_crimson_stem"},
    {"warped_stem", "warped_stem", "warped_stem_top"},
    {"stripped_warped_stem", "stripped_warped_stem", "stripped_warped_stem_top"},
    {"warped_hyphae", "warped_stem", "warped_stem"},
    {"stripped_warped_hyphae", "stripped_warped_stem", "stripped_warped_stem"},
    {"bamboo_block", "bamboo_block", "bamboo_block_top"},
    {"stripped_bamboo_block", "stripped_bamboo_block", "stripped_bamboo_block_top"},
};

void addColumn(const Column& c, std::vector<GeneratedFile>& out) {
  out.push_back(file(
      "model", c.name,
      Json{{"parent", "block/cube_column"}, {"textures", {{"end", block(c.end)}, {"side", block(c.side)}}}}));
  Json variants;
  variants["axis=x"] = Json{{"model", block(c.name)}, {"x", 90}, {"y", 90}};
  variants["axis=y"] = Json{{"model", block(c.name)}};
  variants["axis=z"] = Json{{"model", block(c.name)}, {"x", 90}};
  out.push_back(file("blockstates", c.name, Json{{"variants", variants}}));
}

}  // namespace

void addFamilyFiles(std::vector<GeneratedFile>& out) {
  for (const std::string& wood : woodBlocks()) addWood(wood, out);
  for (const std::string& carpet : carpets()) addCarpet(carpet, out);
  for (const std::string& pane : panes())
    addPane(pane, pane.substr(0, pane.size() - std::string("_pane").size()), pane + "_top", out);
  for (const char* wood : kOakLikeWoods) addOakLike(wood, true, out);
  for (const char* wood : kOakLikeCrafts) addOakLike(wood, false, out);
  addPlates(out);
  for (const Column& c : kColumns) addColumn(c, out);
}

}  // namespace terrasol::packgen
