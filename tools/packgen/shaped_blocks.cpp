// The slabs, stairs and walls of the default pack's materials, and its woods' bark blocks: blockstates
// and models in Minecraft's format, on Minecraft's templates (block/slab, block/stairs,
// block/template_wall_*, block/cube_column), as Minecraft's own files are laid out, so a pack that
// retextures a material retextures its shapes too.

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/paths.h"
#include "packgen.h"
#include "recipes.h"

namespace terrasol::packgen {
namespace {

using Json = nlohmann::ordered_json;

// A material's shapes: `prefix` names them (brick_slab), `block` is its full block (bricks), with its
// side, top and bottom textures.
struct Material {
  const char* prefix;
  const char* block;
  const char *side, *top, *bottom;
  bool slab, stairs, wall;
};

constexpr Material kMaterials[] = {
    {"cobblestone", "cobblestone", "cobblestone", "cobblestone", "cobblestone", true, true, true},
    {"granite", "granite", "granite", "granite", "granite", true, true, true},
    {"polished_granite", "polished_granite", "polished_granite", "polished_granite", "polished_granite", true,
     true, false},
    {"diorite", "diorite", "diorite", "diorite", "diorite", true, true, true},
    {"polished_diorite", "polished_diorite", "polished_diorite", "polished_diorite", "polished_diorite", true,
     true, false},
    {"andesite", "andesite", "andesite", "andesite", "andesite", true, true, true},
    {"polished_andesite", "polished_andesite", "polished_andesite", "polished_andesite", "polished_andesite",
     true, true, false},
    {"brick", "bricks", "bricks", "bricks", "bricks", true, true, true},
    {"stone_brick", "stone_bricks", "stone_bricks", "stone_bricks", "stone_bricks", true, true, true},
    {"mossy_stone_brick", "mossy_stone_bricks", "mossy_stone_bricks", "mossy_stone_bricks",
     "mossy_stone_bricks", true, true, true},
    {"mossy_cobblestone", "mossy_cobblestone", "mossy_cobblestone", "mossy_cobblestone", "mossy_cobblestone",
     true, true, true},
    {"sandstone", "sandstone", "sandstone", "sandstone_top", "sandstone_bottom", true, true, true},
    {"cut_sandstone", "cut_sandstone", "cut_sandstone", "sandstone_top", "sandstone_top", true, false, false},
    {"smooth_stone", "smooth_stone", "smooth_stone", "smooth_stone", "smooth_stone", true, false, false},
    {"tuff", "tuff", "tuff", "tuff", "tuff", true, true, true},
    {"cobbled_deepslate", "cobbled_deepslate", "cobbled_deepslate", "cobbled_deepslate", "cobbled_deepslate",
     true, true, true},
    {"polished_deepslate", "polished_deepslate", "polished_deepslate", "polished_deepslate",
     "polished_deepslate", true, true, true},
    {"red_sandstone", "red_sandstone", "red_sandstone", "red_sandstone_top", "red_sandstone_bottom", true,
     true, true},
    {"cut_red_sandstone", "cut_red_sandstone", "cut_red_sandstone", "red_sandstone_top", "red_sandstone_top",
     true, false, false},
    {"smooth_red_sandstone", "smooth_red_sandstone", "red_sandstone_top", "red_sandstone_top",
     "red_sandstone_top", true, true, false},
    {"quartz", "quartz_block", "quartz_block_side", "quartz_block_top", "quartz_block_bottom", true, true,
     false},
    {"smooth_quartz", "smooth_quartz", "quartz_block_bottom", "quartz_block_bottom", "quartz_block_bottom",
     true, true, false},
    // The materials the building blocks brought (building_blocks.cpp); waxed coppers look as unwaxed.
    {"nether_brick", "nether_bricks", "nether_bricks", "nether_bricks", "nether_bricks", true, true, true},
    {"red_nether_brick", "red_nether_bricks", "red_nether_bricks", "red_nether_bricks", "red_nether_bricks",
     true, true, true},
    {"end_stone_brick", "end_stone_bricks", "end_stone_bricks", "end_stone_bricks", "end_stone_bricks", true,
     true, true},
    {"mud_brick", "mud_bricks", "mud_bricks", "mud_bricks", "mud_bricks", true, true, true},
    {"tuff_brick", "tuff_bricks", "tuff_bricks", "tuff_bricks", "tuff_bricks", true, true, true},
    {"polished_tuff", "polished_tuff", "polished_tuff", "polished_tuff", "polished_tuff", true, true, true},
    {"polished_blackstone", "polished_blackstone", "polished_blackstone", "polished_blackstone",
     "polished_blackstone", true, true, true},
    {"polished_blackstone_brick", "polished_blackstone_bricks", "polished_blackstone_bricks",
     "polished_blackstone_bricks", "polished_blackstone_bricks", true, true, true},
    {"deepslate_brick", "deepslate_bricks", "deepslate_bricks", "deepslate_bricks", "deepslate_bricks", true,
     true, true},
    {"deepslate_tile", "deepslate_tiles", "deepslate_tiles", "deepslate_tiles", "deepslate_tiles", true, true,
     true},
    {"prismarine_brick", "prismarine_bricks", "prismarine_bricks", "prismarine_bricks", "prismarine_bricks",
     true, true, false},
    {"dark_prismarine", "dark_prismarine", "dark_prismarine", "dark_prismarine", "dark_prismarine", true,
     true, false},
    {"purpur", "purpur_block", "purpur_block", "purpur_block", "purpur_block", true, true, false},
    {"resin_brick", "resin_bricks", "resin_bricks", "resin_bricks", "resin_bricks", true, true, true},
    {"smooth_sandstone", "smooth_sandstone", "sandstone_top", "sandstone_top", "sandstone_top", true, true,
     false},
    {"cut_copper", "cut_copper", "cut_copper", "cut_copper", "cut_copper", true, true, false},
    {"exposed_cut_copper", "exposed_cut_copper", "exposed_cut_copper", "exposed_cut_copper",
     "exposed_cut_copper", true, true, false},
    {"weathered_cut_copper", "weathered_cut_copper", "weathered_cut_copper", "weathered_cut_copper",
     "weathered_cut_copper", true, true, false},
    {"oxidized_cut_copper", "oxidized_cut_copper", "oxidized_cut_copper", "oxidized_cut_copper",
     "oxidized_cut_copper", true, true, false},
    {"waxed_cut_copper", "waxed_cut_copper", "cut_copper", "cut_copper", "cut_copper", true, true, false},
    {"waxed_exposed_cut_copper", "waxed_exposed_cut_copper", "exposed_cut_copper", "exposed_cut_copper",
     "exposed_cut_copper", true, true, false},
    {"waxed_weathered_cut_copper", "waxed_weathered_cut_copper", "weathered_cut_copper",
     "weathered_cut_copper", "weathered_cut_copper", true, true, false},
    {"waxed_oxidized_cut_copper", "waxed_oxidized_cut_copper", "oxidized_cut_copper", "oxidized_cut_copper",
     "oxidized_cut_copper", true, true, false},
    {"jungle", "jungle_planks", "jungle_planks", "jungle_planks", "jungle_planks", true, true, false},
    {"cherry", "cherry_planks", "cherry_planks", "cherry_planks", "cherry_planks", true, true, false},
    {"mangrove", "mangrove_planks", "mangrove_planks", "mangrove_planks", "mangrove_planks", true, true,
     false},
    {"bamboo", "bamboo_planks", "bamboo_planks", "bamboo_planks", "bamboo_planks", true, true, false},
    {"crimson", "crimson_planks", "crimson_planks", "crimson_planks", "crimson_planks", true, true, false},
    {"warped", "warped_planks", "warped_planks", "warped_planks", "warped_planks", true, true, false},
    {"pale_oak", "pale_oak_planks", "pale_oak_planks", "pale_oak_planks", "pale_oak_planks", true, true,
     false},
};

std::string block(const std::string& name) {
  return "block/" + name;
}

GeneratedFile file(const std::string& kind, const std::string& name, const Json& json) {
  const std::string dir =
      kind == "blockstates" ? "assets/minecraft/blockstates/" : "assets/minecraft/models/block/";
  return {dir + name + ".json", json.dump(2) + "\n"};
}

Json texturedModel(const std::string& parent, const Material& m) {
  Json textures;
  textures["bottom"] = block(m.bottom);
  textures["top"] = block(m.top);
  textures["side"] = block(m.side);
  return Json{{"parent", block(parent)}, {"textures", textures}};
}

// A variant's model turned by x and y degrees; uvlock keeps its textures on the world's grid.
Json turned(const std::string& model, int x, int y) {
  Json v{{"model", block(model)}};
  if (x != 0) v["x"] = x;
  if (y != 0) v["y"] = y;
  if (x != 0 || y != 0) v["uvlock"] = true;
  return v;
}

// The full block's own model, which a double slab shows.
void addFullBlock(const Material& m, std::vector<GeneratedFile>& out) {
  const bool sameAllRound = std::string(m.side) == m.top && std::string(m.top) == m.bottom;
  Json model = sameAllRound ? Json{{"parent", "block/cube_all"}, {"textures", {{"all", block(m.side)}}}}
                            : texturedModel("cube_bottom_top", m);
  out.push_back(file("model", m.block, model));
}

void addSlab(const Material& m, std::vector<GeneratedFile>& out) {
  const std::string name = std::string(m.prefix) + "_slab";
  out.push_back(file("model", name, texturedModel("slab", m)));
  out.push_back(file("model", name + "_top", texturedModel("slab_top", m)));
  Json variants;
  variants["type=bottom"] = Json{{"model", block(name)}};
  variants["type=top"] = Json{{"model", block(name + "_top")}};
  variants["type=double"] = Json{{"model", block(m.block)}};
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// Minecraft's stairs: east unturned, the others by 90 degrees each; a left corner is the right one
// turned a quarter back, and upside down (x 180) the turns swap.
void addStairs(const Material& m, std::vector<GeneratedFile>& out) {
  const std::string name = std::string(m.prefix) + "_stairs";
  out.push_back(file("model", name, texturedModel("stairs", m)));
  out.push_back(file("model", name + "_inner", texturedModel("inner_stairs", m)));
  out.push_back(file("model", name + "_outer", texturedModel("outer_stairs", m)));
  constexpr std::array<std::pair<const char*, int>, 4> kFacings{
      {{"east", 0}, {"south", 90}, {"west", 180}, {"north", 270}}};
  Json variants;
  for (const auto& [facing, turn] : kFacings) {
    for (const bool top : {false, true}) {
      for (const char* shape : {"straight", "inner_left", "inner_right", "outer_left", "outer_right"}) {
        const std::string s = shape;
        const std::string model =
            s == "straight" ? name : name + (s.starts_with("inner") ? "_inner" : "_outer");
        const bool left = s.ends_with("_left"), right = s.ends_with("_right");
        const int y = (turn + (!top && left ? 270 : 0) + (top && right ? 90 : 0)) % 360;
        const std::string key =
            "facing=" + std::string(facing) + ",half=" + (top ? "top" : "bottom") + ",shape=" + s;
        variants[key] = turned(model, top ? 180 : 0, y);
      }
    }
  }
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

void addWall(const Material& m, std::vector<GeneratedFile>& out) {
  const std::string name = std::string(m.prefix) + "_wall";
  for (const char* part : {"post", "side", "side_tall"}) {
    out.push_back(file("model", name + "_" + part,
                       Json{{"parent", block(std::string("template_wall_") + part)},
                            {"textures", {{"wall", block(m.side)}}}}));
  }
  Json parts = Json::array();
  parts.push_back(Json{{"when", {{"up", "true"}}}, {"apply", {{"model", block(name + "_post")}}}});
  constexpr std::array<std::pair<const char*, int>, 4> kSides{
      {{"north", 0}, {"east", 90}, {"south", 180}, {"west", 270}}};
  for (const auto& [side, y] : kSides) {
    for (const char* height : {"low", "tall"}) {
      Json apply{{"model", block(name + (std::string(height) == "low" ? "_side" : "_side_tall"))},
                 {"uvlock", true}};
      if (y != 0) apply["y"] = y;
      parts.push_back(Json{{"when", {{side, height}}}, {"apply", apply}});
    }
  }
  out.push_back(file("blockstates", name, Json{{"multipart", parts}}));
}

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

void addPane(const std::string& name, std::vector<GeneratedFile>& out) {
  const std::string glass = name.substr(0, name.size() - std::string("_pane").size());
  for (const char* part : {"post", "side", "side_alt", "noside", "noside_alt"}) {
    out.push_back(file("model", name + "_" + part,
                       Json{{"parent", block(std::string("template_glass_pane_") + part)},
                            {"textures", {{"pane", block(glass)}, {"edge", block(name + "_top")}}}}));
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

// Minecraft's pressure-plate templates: a plate a sixteenth high (half that pressed) inset by one on
// each side, its rim showing the texture's bottom row.
Json number(double v) {
  return v == static_cast<int>(v) ? Json(static_cast<int>(v)) : Json(v);
}

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

std::vector<GeneratedFile> generateShapedBlockFiles() {
  std::vector<GeneratedFile> out;
  for (const Material& m : kMaterials) {
    if (m.slab) addFullBlock(m, out);
    if (m.slab) addSlab(m, out);
    if (m.stairs) addStairs(m, out);
    if (m.wall) addWall(m, out);
  }
  for (const std::string& wood : woodBlocks()) addWood(wood, out);
  for (const std::string& carpet : carpets()) addCarpet(carpet, out);
  for (const std::string& pane : panes()) addPane(pane, out);
  for (const char* wood : kOakLikeWoods) addOakLike(wood, true, out);
  for (const char* wood : kOakLikeCrafts) addOakLike(wood, false, out);
  addPlates(out);
  for (const Column& c : kColumns) addColumn(c, out);
  return out;
}

std::vector<std::string> shapedBlockNames() {
  std::vector<std::string> names;
  for (const Material& m : kMaterials) {
    if (m.slab) names.push_back(std::string(m.prefix) + "_slab");
    if (m.stairs) names.push_back(std::string(m.prefix) + "_stairs");
    if (m.wall) names.push_back(std::string(m.prefix) + "_wall");
  }
  for (const std::string& wood : woodBlocks()) names.push_back(wood);
  for (const std::string& carpet : carpets()) names.push_back(carpet);
  for (const std::string& pane : panes()) names.push_back(pane);
  for (const char* wood : kOakLikeWoods) {
    for (const char* block : {"_log", "_fence", "_fence_gate", "_door", "_trapdoor"})
      names.push_back(wood + std::string(block));
    names.push_back("stripped_" + std::string(wood) + "_log");
  }
  for (const char* wood : kOakLikeCrafts) {
    for (const char* block : {"_fence", "_fence_gate", "_door", "_trapdoor"})
      names.push_back(wood + std::string(block));
  }
  for (const auto& [material, texture] : kPlates) names.push_back(std::string(material) + "_pressure_plate");
  for (const Column& c : kColumns) names.push_back(c.name);
  return names;
}

}  // namespace terrasol::packgen
