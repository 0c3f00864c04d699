// The slabs, stairs and walls of the default pack's materials: blockstates and models in Minecraft's
// format, on Minecraft's templates (block/slab, block/stairs, block/template_wall_*), as Minecraft's
// own files are laid out, so a pack that retextures a material retextures its shapes too. The other
// families come from block_family_files.cpp.

#include <array>
#include <map>

#include "block_files.h"
#include "core/error.h"

namespace terrasol::packgen {
namespace {

// A material's shapes: `prefix` names them (brick_slab), `block` is its full block (bricks), with its
// side, top and bottom textures.
struct Material {
  const char* prefix;
  const char* block;
  const char *side, *top, *bottom;
  bool slab, stairs, wall;
  // A slab side of its own (smooth stone's shows the seam), on its slabs and on a double slab's model
  // (PREFIX_slab_double), as Minecraft draws them; null: the block's side.
  const char* slabSide = nullptr;
};

constexpr Material kMaterials[] = {
    {"prismarine", "prismarine", "prismarine", "prismarine", "prismarine", true, true, true},
    {"blackstone", "blackstone", "blackstone", "blackstone_top", "blackstone_top", true, true, true},
    {"bamboo_mosaic", "bamboo_mosaic", "bamboo_mosaic", "bamboo_mosaic", "bamboo_mosaic", true, true, false},
    {"petrified_oak", "oak_planks", "oak_planks", "oak_planks", "oak_planks", true, false, false},
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
    {"smooth_stone", "smooth_stone", "smooth_stone", "smooth_stone", "smooth_stone", true, false, false,
     "smooth_stone_slab_side"},
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

Json texturedModel(const std::string& parent, const Material& m) {
  Json textures;
  textures["bottom"] = block(m.bottom);
  textures["top"] = block(m.top);
  textures["side"] = block(m.side);
  return Json{{"parent", block(parent)}, {"textures", textures}};
}

// The full block's own model, which a double slab shows.
void addFullBlock(const Material& m, std::vector<GeneratedFile>& out) {
  const bool sameAllRound = std::string(m.side) == m.top && std::string(m.top) == m.bottom;
  Json model = sameAllRound ? Json{{"parent", "block/cube_all"}, {"textures", {{"all", block(m.side)}}}}
                            : texturedModel("cube_bottom_top", m);
  out.push_back(file("model", m.block, model));
}

void addSlab(Material m, std::vector<GeneratedFile>& out) {
  const std::string name = std::string(m.prefix) + "_slab";
  std::string doubleModel = m.block;
  if (m.slabSide) {
    m.side = m.slabSide;
    doubleModel = name + "_double";
    out.push_back(file("model", doubleModel, texturedModel("cube_bottom_top", m)));
  }
  out.push_back(file("model", name, texturedModel("slab", m)));
  out.push_back(file("model", name + "_top", texturedModel("slab_top", m)));
  Json variants;
  variants["type=bottom"] = Json{{"model", block(name)}};
  variants["type=top"] = Json{{"model", block(name + "_top")}};
  variants["type=double"] = Json{{"model", block(doubleModel)}};
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

}  // namespace

std::vector<GeneratedFile> generateShapedBlockFiles() {
  std::vector<GeneratedFile> out;
  for (const Material& m : kMaterials) {
    if (m.slab) addFullBlock(m, out);
    if (m.slab) addSlab(m, out);
    if (m.stairs) addStairs(m, out);
    if (m.wall) addWall(m, out);
  }
  addFamilyFiles(out);
  addFurnitureFiles(out);
  addWorkshopFiles(out);
  addHomeFiles(out);
  addRedstoneFiles(out);
  addPlantFiles(out);
  addCubeFiles(out);
  // Two families writing one file must agree on it.
  std::map<std::string, const std::string*> written;
  for (const GeneratedFile& f : out) {
    const auto [at, added] = written.emplace(f.path, &f.text);
    if (!added && *at->second != f.text) throw Error(f.path + ": written twice, differently");
  }
  return out;
}

std::vector<std::string> shapedBlockNames() {
  // Every blockstates file written is a block's.
  const std::string dir = "assets/minecraft/blockstates/";
  std::vector<std::string> names;
  for (const GeneratedFile& f : generateShapedBlockFiles()) {
    if (f.path.starts_with(dir)) names.push_back(f.path.substr(dir.size(), f.path.size() - dir.size() - 5));
  }
  return names;
}

}  // namespace terrasol::packgen
