// The home's small blocks in Minecraft's layout: cakes and candles, lanterns, chains, bars and
// lightning rods in every copper age, and flower pots with every plant.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "block_files.h"
#include "core/error.h"
#include "core/paths.h"
#include "recipes.h"

namespace terrasol::packgen {
namespace {

// Cake with `bites` eaten from the west, and a candle on top where there is one.
Json cake(int bites, const std::string& candle) {
  const double x0 = 1 + 2 * bites;
  Json textures{{"top", block("cake_top")},
                {"side", block("cake_side")},
                {"bottom", block("cake_bottom")},
                {"inside", block("cake_inner")}};
  Json elements =
      Json::array({box({x0, 0, 1}, {15, 8, 15}, "#side", "nse"), box({x0, 0, 1}, {15, 8, 15}, "#top", "u"),
                   box({x0, 0, 1}, {15, 8, 15}, "#bottom", "d"),
                   box({x0, 0, 1}, {15, 8, 15}, bites > 0 ? "#inside" : "#side", "w")});
  if (!candle.empty()) {
    textures["candle"] = block(candle);
    elements.push_back(box({7, 8, 7}, {9, 14, 9}, "#candle", "unswe"));
  }
  return elementModel(textures, elements);
}

// Candles: one to four of a colour, lit or not, as Minecraft stands them.
void addCandles(const std::string& name, std::vector<GeneratedFile>& out) {
  using Boxes = std::vector<std::array<double, 6>>;
  const std::array<Boxes, 4> kStands = {
      {{{7, 0, 7, 9, 6, 9}},
       {{5, 0, 7, 7, 6, 9}, {9, 0, 6, 11, 5, 8}},
       {{7, 0, 9, 9, 6, 11}, {5, 0, 7, 7, 5, 9}, {8, 0, 6, 10, 4, 8}},
       {{6, 0, 8, 8, 6, 10}, {9, 0, 8, 11, 5, 10}, {6, 0, 5, 8, 5, 7}, {9, 0, 5, 11, 4, 7}}}};
  Json variants;
  for (int count = 1; count <= 4; ++count) {
    for (const bool lit : {false, true}) {
      const std::string model = name + "_" + std::to_string(count) + (lit ? "_lit" : "");
      Json elements = Json::array();
      for (const auto& b : kStands[static_cast<std::size_t>(count - 1)])
        elements.push_back(box({b[0], b[1], b[2]}, {b[3], b[4], b[5]}, "#candle"));
      out.push_back(
          file("model", model, elementModel(Json{{"candle", block(name + (lit ? "_lit" : ""))}}, elements)));
      variants["candles=" + std::to_string(count) + ",lit=" + (lit ? "true" : "false")] =
          Json{{"model", block(model)}};
    }
  }
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
  const std::string cakeName = name + "_cake";
  out.push_back(file("model", cakeName, cake(0, name)));
  out.push_back(file("model", cakeName + "_lit", cake(0, name + "_lit")));
  out.push_back(file("blockstates", cakeName,
                     Json{{"variants",
                           {{"lit=false", {{"model", block(cakeName)}}},
                            {"lit=true", {{"model", block(cakeName + "_lit")}}}}}}));
}

void addCakes(std::vector<GeneratedFile>& out) {
  Json variants;
  for (int bites = 0; bites <= 6; ++bites) {
    const std::string model = bites == 0 ? "cake" : "cake_slice" + std::to_string(bites);
    out.push_back(file("model", model, cake(bites, "")));
    variants["bites=" + std::to_string(bites)] = Json{{"model", block(model)}};
  }
  out.push_back(file("blockstates", "cake", Json{{"variants", variants}}));
  addCandles("candle", out);
  for (const auto& [colour, rgb] : kDyes) addCandles(std::string(colour) + "_candle", out);
}

// Lanterns of soul fire and copper: the lantern's model on their own textures.
void addLanterns(std::vector<GeneratedFile>& out) {
  const auto pack = resourcePackDir() / "default" / "assets" / "minecraft";
  const std::string lantern = readTextFile(pack / "models" / "block" / "lantern.json");
  const auto retextured = [&](const std::string& texture) {
    std::string text = lantern;
    for (std::size_t at = text.find("block/lantern"); at != std::string::npos;
         at = text.find("block/lantern", at + 1))
      text.replace(at, std::string("block/lantern").size(), block(texture));
    return text;
  };
  std::vector<std::pair<std::string, std::string>> lanterns{{"soul_lantern", "soul_lantern"}};
  for (const char* age : kCopperAges) {
    const std::string texture = std::string(age) + "copper_lantern";
    lanterns.emplace_back(texture, texture);
    lanterns.emplace_back("waxed_" + texture, texture);
  }
  for (const auto& [name, texture] : lanterns) {
    if (name == texture)
      out.push_back({"assets/minecraft/models/block/" + name + ".json", retextured(texture)});
    out.push_back(file("blockstates", name, single(texture)));
  }
}

// Chains, bars and lightning rods of iron and of copper in every age, waxed or not.
void addMetalWork(std::vector<GeneratedFile>& out) {
  const auto chain = [&](const std::string& name, const std::string& texture) {
    out.push_back(
        file("model", name,
             elementModel(Json{{"chain", block(texture)}},
                          Json::array({turnedBox({6.5, 0, 8}, {9.5, 16, 8}, "#chain", "ns", 45),
                                       turnedBox({8, 0, 6.5}, {8, 16, 9.5}, "#chain", "we", 45)}))));
  };
  const auto rod = [&](const std::string& name, const std::string& texture) {
    out.push_back(file(
        "model", name,
        elementModel(Json{{"rod", block(texture)}}, Json::array({box({7, 0, 7}, {9, 12, 9}, "#rod", "dnswe"),
                                                                 box({6, 12, 6}, {10, 16, 10}, "#rod")}))));
  };
  chain("iron_chain", "iron_chain");
  out.push_back(file("blockstates", "iron_chain", Json{{"variants", axisVariants("iron_chain")}}));
  addPane("iron_bars", "iron_bars", "iron_bars", out);
  for (const char* age : kCopperAges) {
    const std::string a = age, metal = a.empty() ? "copper_block" : a + "copper";
    chain(a + "copper_chain", a + "copper_chain");
    rod(a + "lightning_rod", metal);
    for (const std::string& wax : {std::string(), std::string("waxed_")}) {
      out.push_back(file("blockstates", wax + a + "copper_chain",
                         Json{{"variants", axisVariants(a + "copper_chain")}}));
      out.push_back(file("blockstates", wax + a + "lightning_rod",
                         Json{{"variants", pointingVariants(a + "lightning_rod")}}));
      addPane(wax + a + "copper_bars", a + "copper_bars", a + "copper_bars", out);
    }
  }
}

// Flower pots: a pot of clay with soil, and each plant Minecraft pots on two crossed sheets.
constexpr std::array<std::pair<const char*, const char*>, 36> kPotted = {
    {{"potted_torchflower", "torchflower"},
     {"potted_oak_sapling", "oak_sapling"},
     {"potted_spruce_sapling", "spruce_sapling"},
     {"potted_birch_sapling", "birch_sapling"},
     {"potted_jungle_sapling", "jungle_sapling"},
     {"potted_acacia_sapling", "acacia_sapling"},
     {"potted_cherry_sapling", "cherry_sapling"},
     {"potted_dark_oak_sapling", "dark_oak_sapling"},
     {"potted_pale_oak_sapling", "pale_oak_sapling"},
     {"potted_mangrove_propagule", "mangrove_propagule"},
     {"potted_fern", "fern"},
     {"potted_dandelion", "dandelion"},
     {"potted_poppy", "poppy"},
     {"potted_blue_orchid", "blue_orchid"},
     {"potted_allium", "allium"},
     {"potted_azure_bluet", "azure_bluet"},
     {"potted_red_tulip", "red_tulip"},
     {"potted_orange_tulip", "orange_tulip"},
     {"potted_white_tulip", "white_tulip"},
     {"potted_pink_tulip", "pink_tulip"},
     {"potted_oxeye_daisy", "oxeye_daisy"},
     {"potted_cornflower", "cornflower"},
     {"potted_lily_of_the_valley", "lily_of_the_valley"},
     {"potted_wither_rose", "wither_rose"},
     {"potted_red_mushroom", "red_mushroom"},
     {"potted_brown_mushroom", "brown_mushroom"},
     {"potted_dead_bush", "dead_bush"},
     {"potted_crimson_fungus", "crimson_fungus"},
     {"potted_warped_fungus", "warped_fungus"},
     {"potted_crimson_roots", "crimson_roots_pot"},
     {"potted_warped_roots", "warped_roots_pot"},
     {"potted_azalea_bush", "azalea_plant"},
     {"potted_flowering_azalea_bush", "flowering_azalea_plant"},
     {"potted_open_eyeblossom", "open_eyeblossom"},
     {"potted_closed_eyeblossom", "closed_eyeblossom"},
     {"potted_bamboo", "bamboo_stalk"}}};

Json pot() {
  return Json::array({box({5, 0, 5}, {6, 6, 11}, "#pot"), box({10, 0, 5}, {11, 6, 11}, "#pot"),
                      box({6, 0, 5}, {10, 6, 6}, "#pot"), box({6, 0, 10}, {10, 6, 11}, "#pot"),
                      box({6, 0, 6}, {10, 4, 10}, "#dirt", "du")});
}

void addFlowerPots(std::vector<GeneratedFile>& out) {
  const Json potTextures{{"pot", block("flower_pot")}, {"dirt", block("dirt")}};
  addModelBlock("flower_pot", elementModel(potTextures, pot()), out);
  for (const auto& [name, plant] : kPotted) {
    Json textures = potTextures;
    textures["plant"] = block(plant);
    Json elements = pot();
    elements.push_back(turnedBox({2.6, 4, 8}, {13.4, 16, 8}, "#plant", "ns", 45));
    elements.push_back(turnedBox({8, 4, 2.6}, {8, 16, 13.4}, "#plant", "we", 45));
    addModelBlock(name, elementModel(textures, elements), out);
  }
  Json cactus = pot();
  cactus.push_back(box({6, 4, 6}, {10, 15, 10}, "#cactus", "unswe"));
  addModelBlock(
      "potted_cactus",
      elementModel(
          Json{{"pot", block("flower_pot")}, {"dirt", block("dirt")}, {"cactus", block("cactus_side")}},
          cactus),
      out);
}

}  // namespace

void addHomeFiles(std::vector<GeneratedFile>& out) {
  addCakes(out);
  addLanterns(out);
  addMetalWork(out);
  addFlowerPots(out);
}

}  // namespace terrasol::packgen
