// Full blocks beyond the plain cubes blocks.json derives: soils with their own tops, chiseled and
// decorated stones, columns, blocks with a front (pumpkins, smokers, looms, nests), barrels, tables,
// glazed terracotta in sixteen colours, chiseled copper and grates, iron and copper doors and
// trapdoors, the nether-brick fence, portals and the cube-like blocks of trials and spawners.

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>

#include "block_files.h"
#include "core/error.h"
#include "core/paths.h"
#include "recipes.h"

namespace terrasol::packgen {
namespace {

Json cubeAll(const std::string& texture) {
  return child("block/cube_all", Json{{"all", block(texture)}});
}
Json column(const std::string& side, const std::string& end) {
  return child("block/cube_column", Json{{"end", block(end)}, {"side", block(side)}});
}
Json bottomTop(const std::string& side, const std::string& top, const std::string& bottom) {
  return child("block/cube_bottom_top",
               Json{{"top", block(top)}, {"bottom", block(bottom)}, {"side", block(side)}});
}
// A cube with a front on the north side.
Json fronted(const std::string& front, const std::string& side, const std::string& top,
             const std::string& bottom) {
  return child("block/cube", Json{{"particle", block(side)},
                                  {"north", block(front)},
                                  {"south", block(side)},
                                  {"east", block(side)},
                                  {"west", block(side)},
                                  {"up", block(top)},
                                  {"down", block(bottom)}});
}

void addCubes(std::vector<GeneratedFile>& out) {
  addModelBlock("podzol", bottomTop("podzol_side", "podzol_top", "dirt"), out);
  addModelBlock("mycelium", bottomTop("mycelium_side", "mycelium_top", "dirt"), out);
  addModelBlock("crimson_nylium", bottomTop("crimson_nylium_side", "crimson_nylium", "netherrack"), out);
  addModelBlock("warped_nylium", bottomTop("warped_nylium_side", "warped_nylium", "netherrack"), out);
  // Their models come with their slabs (shaped_blocks.cpp).
  for (const char* name : {"bamboo_mosaic", "blackstone"})
    out.push_back(file("blockstates", name, single(name)));
  for (const char* name : {"chiseled_stone_bricks", "chiseled_resin_bricks", "chiseled_polished_blackstone",
                           "gilded_blackstone", "chiseled_nether_bricks", "azalea_leaves",
                           "flowering_azalea_leaves", "slime_block", "spawner", "end_gateway"})
    addModelBlock(name, cubeAll(name), out);
  out.push_back(file("blockstates", "infested_chiseled_stone_bricks", single("chiseled_stone_bricks")));
  addModelBlock("honey_block", bottomTop("honey_block_side", "honey_block_top", "honey_block_bottom"), out);
  addModelBlock("mangrove_roots", column("mangrove_roots_side", "mangrove_roots_top"), out);
  addModelBlock("ancient_debris", column("ancient_debris_side", "ancient_debris_top"), out);
  addModelBlock("lodestone", column("lodestone_side", "lodestone_top"), out);
  addModelBlock("chiseled_tuff", column("chiseled_tuff", "chiseled_tuff_top"), out);
  addModelBlock("chiseled_tuff_bricks", column("chiseled_tuff_bricks", "chiseled_tuff_bricks_top"), out);
  addModelBlock("chiseled_deepslate", cubeAll("chiseled_deepslate"), out);
  addModelBlock(
      "reinforced_deepslate",
      bottomTop("reinforced_deepslate_side", "reinforced_deepslate_top", "reinforced_deepslate_bottom"), out);
  addModelBlock("dried_kelp_block", bottomTop("dried_kelp_side", "dried_kelp_top", "dried_kelp_bottom"), out);
  addModelBlock("sculk_catalyst",
                bottomTop("sculk_catalyst_side", "sculk_catalyst_top", "sculk_catalyst_bottom"), out);
  addModelBlock(
      "trial_spawner",
      bottomTop("trial_spawner_side_inactive", "trial_spawner_top_inactive", "trial_spawner_bottom"), out);
  // Tables as Minecraft faces them: a front to the north and south, their sides east and west.
  const auto table = [&](const std::string& name, const std::string& front, const std::string& side,
                         const std::string& west, const std::string& top, const std::string& bottom) {
    addModelBlock(name,
                  child("block/cube", Json{{"particle", block(front)},
                                           {"north", block(front)},
                                           {"south", block(front)},
                                           {"east", block(side)},
                                           {"west", block(west)},
                                           {"up", block(top)},
                                           {"down", block(bottom)}}),
                  out);
  };
  table("cartography_table", "cartography_table_side3", "cartography_table_side1", "cartography_table_side2",
        "cartography_table_top", "dark_oak_planks");
  table("fletching_table", "fletching_table_front", "fletching_table_side", "fletching_table_side",
        "fletching_table_top", "birch_planks");
  table("smithing_table", "smithing_table_front", "smithing_table_side", "smithing_table_side",
        "smithing_table_top", "smithing_table_bottom");
  for (const char* columnBlock : {"muddy_mangrove_roots", "ochre_froglight", "verdant_froglight",
                                  "pearlescent_froglight", "creaking_heart"}) {
    const std::string n = columnBlock;
    out.push_back(file("model", n, column(n + "_side", n + "_top")));
    out.push_back(file("blockstates", n, Json{{"variants", axisVariants(n)}}));
  }
  // Sand and gravel with something buried: brushed away in four steps.
  for (const std::string name : {"suspicious_sand", "suspicious_gravel"}) {
    Json variants;
    for (int d = 0; d <= 3; ++d) {
      const std::string model = name + "_" + std::to_string(d);
      out.push_back(file("model", model, cubeAll(model)));
      variants["dusted=" + std::to_string(d)] = variant(model);
    }
    out.push_back(file("blockstates", name, Json{{"variants", variants}}));
  }
  // Frosted ice melts through four ages; the respawn anchor shows its charge on top.
  Json ice;
  for (int age = 0; age <= 3; ++age) {
    const std::string model = "frosted_ice_" + std::to_string(age);
    out.push_back(file("model", model, cubeAll(model)));
    ice["age=" + std::to_string(age)] = variant(model);
  }
  out.push_back(file("blockstates", "frosted_ice", Json{{"variants", ice}}));
  Json anchor;
  for (int charges = 0; charges <= 4; ++charges) {
    const std::string model = "respawn_anchor_" + std::to_string(charges);
    out.push_back(file(
        "model", model,
        bottomTop("respawn_anchor_side" + std::to_string(charges),
                  charges == 0 ? "respawn_anchor_top_off" : "respawn_anchor_top", "respawn_anchor_bottom")));
    anchor["charges=" + std::to_string(charges)] = variant(model);
  }
  out.push_back(file("blockstates", "respawn_anchor", Json{{"variants", anchor}}));
}

void addFrontedBlocks(std::vector<GeneratedFile>& out) {
  const auto facing = [&](const std::string& name, const Json& model) {
    out.push_back(file("model", name, model));
    out.push_back(file("blockstates", name,
                       Json{{"variants", facingVariants([&](const std::string&) { return name; })}}));
  };
  facing("carved_pumpkin", fronted("carved_pumpkin", "pumpkin_side", "pumpkin_top", "pumpkin_top"));
  facing("jack_o_lantern", fronted("jack_o_lantern", "pumpkin_side", "pumpkin_top", "pumpkin_top"));
  // Furnaces show their fire while lit.
  const auto furnace = [&](const std::string& name, const std::string& side, const std::string& top,
                           const std::string& bottom) {
    out.push_back(file("model", name, fronted(name + "_front", side, top, bottom)));
    out.push_back(file("model", name + "_on", fronted(name + "_front_on", side, top, bottom)));
    Json variants = facingVariants([&](const std::string&) { return name; }, "lit=false,");
    variants.update(facingVariants([&](const std::string&) { return name + "_on"; }, "lit=true,"));
    out.push_back(file("blockstates", name, Json{{"variants", variants}}));
  };
  furnace("furnace", "furnace_side", "furnace_top", "furnace_top");
  furnace("smoker", "smoker_side", "smoker_top", "smoker_bottom");
  furnace("blast_furnace", "blast_furnace_side", "blast_furnace_top", "blast_furnace_top");
  facing("loom", fronted("loom_front", "loom_side", "loom_top", "loom_bottom"));
  facing("chiseled_bookshelf", fronted("chiseled_bookshelf_empty", "chiseled_bookshelf_side",
                                       "chiseled_bookshelf_top", "chiseled_bookshelf_top"));
  facing("vault", fronted("vault_front_off", "vault_side_off", "vault_top", "vault_bottom"));
  // Nests and hives show honey at the front when full (level 5).
  for (const std::string name : {"bee_nest", "beehive"}) {
    const std::string top = name == "bee_nest" ? "bee_nest_top" : "beehive_end";
    const std::string bottom = name == "bee_nest" ? "bee_nest_bottom" : "beehive_end";
    out.push_back(file("model", name, fronted(name + "_front", name + "_side", top, bottom)));
    out.push_back(
        file("model", name + "_honey", fronted(name + "_front_honey", name + "_side", top, bottom)));
    Json variants;
    for (int level = 0; level <= 5; ++level)
      variants.update(facingVariants([&](const std::string&) { return level == 5 ? name + "_honey" : name; },
                                     "honey_level=" + std::to_string(level) + ","));
    out.push_back(file("blockstates", name, Json{{"variants", variants}}));
  }
  // Barrels point their lid along facing.
  out.push_back(file("model", "barrel", bottomTop("barrel_side", "barrel_top", "barrel_bottom")));
  out.push_back(file("model", "barrel_open", bottomTop("barrel_side", "barrel_top_open", "barrel_bottom")));
  Json barrel = pointingVariants("barrel", "open=false,");
  barrel.update(pointingVariants("barrel_open", "open=true,"));
  out.push_back(file("blockstates", "barrel", Json{{"variants", barrel}}));
}

// Glazed terracotta: Minecraft's template turns the pattern on each face so that four blocks laid
// in a ring make a larger figure.
void addGlazedTerracotta(std::vector<GeneratedFile>& out) {
  Json faces;
  constexpr std::array<std::pair<const char*, int>, 6> kTurns = {
      {{"down", 0}, {"up", 90}, {"north", 0}, {"south", 180}, {"west", 90}, {"east", 270}}};
  for (const auto& [face, rotation] : kTurns) {
    Json f{{"uv", {0, 0, 16, 16}}, {"texture", "#pattern"}, {"cullface", face}};
    if (rotation != 0) f["rotation"] = rotation;
    faces[face] = f;
  }
  out.push_back(
      file("model", "template_glazed_terracotta",
           Json{{"parent", "block/block"},
                {"textures", {{"particle", "#pattern"}}},
                {"elements", {Json{{"from", {0, 0, 0}}, {"to", {16, 16, 16}}, {"faces", faces}}}}}));
  for (const auto& [colour, rgb] : kDyes) {
    const std::string name = std::string(colour) + "_glazed_terracotta";
    out.push_back(
        file("model", name, child("block/template_glazed_terracotta", Json{{"pattern", block(name)}})));
    out.push_back(file("blockstates", name,
                       Json{{"variants", facingVariants([&](const std::string&) { return name; })}}));
  }
}

// Renamed copies of oak's door, trapdoor or fence files for another material; `retexture` then
// names that material's texture where oak's planks were.
void addRenamedOak(const std::vector<std::string>& files, const std::string& prefix,
                   const std::string& planks, std::vector<GeneratedFile>& out) {
  const std::filesystem::path pack = resourcePackDir() / "default" / "assets" / "minecraft";
  const auto rename = [&](std::string text) {
    for (std::size_t at = text.find("oak_"); at != std::string::npos;
         at = text.find("oak_", at + prefix.size()))
      text.replace(at, 4, prefix);
    if (!planks.empty()) {
      const std::string from = "block/" + prefix + "planks";
      for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + 1))
        text.replace(at, from.size(), block(planks));
    }
    return text;
  };
  for (const std::string& f : files)
    out.push_back({"assets/minecraft/" + rename(f) + ".json", rename(readTextFile(pack / (f + ".json")))});
}

void addDoors(std::vector<GeneratedFile>& out) {
  const std::vector<std::string> door = {"blockstates/oak_door", "models/block/oak_door_bottom_left",
                                         "models/block/oak_door_bottom_right",
                                         "models/block/oak_door_top_left", "models/block/oak_door_top_right"};
  const std::vector<std::string> trapdoor = {"blockstates/oak_trapdoor", "models/block/oak_trapdoor_bottom",
                                             "models/block/oak_trapdoor_open",
                                             "models/block/oak_trapdoor_top"};
  addRenamedOak(door, "iron_", "", out);
  addRenamedOak(trapdoor, "iron_", "", out);
  for (const std::string age : kCopperAges) {
    addRenamedOak(door, age + "copper_", "", out);
    addRenamedOak(trapdoor, age + "copper_", "", out);
    // Waxed copper looks as the copper it keeps.
    for (const std::string kind : {"door", "trapdoor"}) {
      const std::string name = age + "copper_" + kind;
      const auto states = std::find_if(out.begin(), out.end(), [&](const GeneratedFile& f) {
        return f.path == "assets/minecraft/blockstates/" + name + ".json";
      });
      out.push_back({"assets/minecraft/blockstates/waxed_" + name + ".json", states->text});
    }
    addModelBlock(age + "chiseled_copper", cubeAll(age + "chiseled_copper"), out);
    out.push_back(file("blockstates", "waxed_" + age + "chiseled_copper", single(age + "chiseled_copper")));
    addModelBlock(age + "copper_grate", cubeAll(age + "copper_grate"), out);
    out.push_back(file("blockstates", "waxed_" + age + "copper_grate", single(age + "copper_grate")));
  }
  addRenamedOak({"blockstates/oak_fence", "models/block/oak_fence_post", "models/block/oak_fence_side"},
                "nether_brick_", "nether_bricks", out);
}

void addPortals(std::vector<GeneratedFile>& out) {
  const Json portal{{"portal", block("nether_portal")}};
  out.push_back(file("model", "nether_portal",
                     elementModel(portal, Json::array({box({0, 0, 6}, {16, 16, 10}, "#portal", "ns")}))));
  out.push_back(
      file("blockstates", "nether_portal",
           Json{{"variants",
                 {{"axis=x", variant("nether_portal")}, {"axis=z", variant("nether_portal", 0, 90)}}}}));
  addModelBlock("end_portal",
                elementModel(Json{{"portal", block("end_portal")}},
                             Json::array({box({0, 12, 0}, {16, 12, 16}, "#portal", "u")})),
                out);
  out.push_back(file("model", "end_rod",
                     elementModel(Json{{"rod", block("end_rod")}},
                                  Json::array({box({6, 0, 6}, {10, 1, 10}, "#rod"),
                                               box({7, 1, 7}, {9, 16, 9}, "#rod", "unswe")}))));
  out.push_back(file("blockstates", "end_rod", Json{{"variants", pointingVariants("end_rod")}}));
}

}  // namespace

void addCubeFiles(std::vector<GeneratedFile>& out) {
  addCubes(out);
  addFrontedBlocks(out);
  addGlazedTerracotta(out);
  addDoors(out);
  addPortals(out);
}

}  // namespace terrasol::packgen
