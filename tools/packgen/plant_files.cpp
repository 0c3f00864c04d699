// Plants and growing things in Minecraft's layout: crosses, crops by age, stems, double plants,
// coral and coral fans, vines and the other growths on a block's faces, mushroom blocks, pickles,
// eggs, dripstone, amethyst buds, dripleaves, azaleas, petals, bamboo, chorus, cocoa and fire.

#include <array>
#include <string>
#include <vector>

#include "block_files.h"

namespace terrasol::packgen {
namespace {

// A cross of `texture` named `model` (tinted by the biome where `tinted`).
void addCross(const std::string& model, const std::string& texture, std::vector<GeneratedFile>& out,
              bool tinted = false) {
  out.push_back(file("model", model,
                     child(tinted ? "block/tinted_cross" : "block/cross", Json{{"cross", block(texture)}})));
}

void addCrossBlock(const std::string& name, std::vector<GeneratedFile>& out, bool tinted = false) {
  addCross(name, name, out, tinted);
  out.push_back(file("blockstates", name, single(name)));
}

// A block whose `property` runs through `values`, each drawn by the model `modelOf(value)`.
void addByValue(const std::string& name, const std::string& property, const std::vector<std::string>& values,
                const std::function<std::string(const std::string&)>& modelOf,
                std::vector<GeneratedFile>& out) {
  Json variants;
  for (const std::string& v : values) variants[property + "=" + v] = variant(modelOf(v));
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

std::vector<std::string> numbers(int first, int last) {
  std::vector<std::string> out;
  for (int i = first; i <= last; ++i) out.push_back(std::to_string(i));
  return out;
}

// Minecraft's crop template: four sheets in a hash, and the crosses' tinted form.
void addTemplates(std::vector<GeneratedFile>& out) {
  out.push_back(file("model", "crop",
                     Json{{"ambientocclusion", false},
                          {"textures", {{"particle", "#crop"}}},
                          {"elements", Json::array({box({4, 0, 0}, {4, 16, 16}, "#crop", "we"),
                                                    box({12, 0, 0}, {12, 16, 16}, "#crop", "we"),
                                                    box({0, 0, 4}, {16, 16, 4}, "#crop", "ns"),
                                                    box({0, 0, 12}, {16, 16, 12}, "#crop", "ns")})}}));
  Json tinted = Json::array({turnedBox({0.8, 0, 8}, {15.2, 16, 8}, "#cross", "ns", 45),
                             turnedBox({8, 0, 0.8}, {8, 16, 15.2}, "#cross", "we", 45)});
  for (Json& e : tinted) {
    e["rotation"]["rescale"] = true;
    for (auto& [name, face] : e["faces"].items()) face["tintindex"] = 0;
  }
  out.push_back(
      file("model", "tinted_cross",
           Json{{"ambientocclusion", false}, {"textures", {{"particle", "#cross"}}}, {"elements", tinted}}));
}

void addCrops(std::vector<GeneratedFile>& out) {
  const auto crop = [&](const std::string& name, const std::vector<int>& stageOfAge) {
    int stages = 0;
    for (int s : stageOfAge) stages = std::max(stages, s + 1);
    for (int s = 0; s < stages; ++s) {
      const std::string model = name + "_stage" + std::to_string(s);
      out.push_back(file("model", model, child("block/crop", Json{{"crop", block(model)}})));
    }
    addByValue(
        name, "age", numbers(0, static_cast<int>(stageOfAge.size()) - 1),
        [&](const std::string& age) { return name + "_stage" + std::to_string(stageOfAge[std::stoul(age)]); },
        out);
  };
  crop("wheat", {0, 1, 2, 3, 4, 5, 6, 7});
  crop("carrots", {0, 0, 1, 1, 2, 2, 2, 3});
  crop("potatoes", {0, 0, 1, 1, 2, 2, 2, 3});
  crop("beetroots", {0, 1, 2, 3});
  crop("nether_wart", {0, 1, 1, 2});
  for (const char* name : {"torchflower_crop", "sweet_berry_bush"}) {
    const std::string n = name;
    const int last = n == "torchflower_crop" ? 1 : 3;
    for (int s = 0; s <= last; ++s)
      addCross(n + "_stage" + std::to_string(s), n + "_stage" + std::to_string(s), out);
    addByValue(
        n, "age", numbers(0, last), [&](const std::string& age) { return n + "_stage" + age; }, out);
  }
  // Stems grow two sixteenths an age; grown, one bends toward its fruit.
  for (const std::string fruit : {"pumpkin", "melon"}) {
    const std::string stem = fruit + "_stem";
    for (int age = 0; age <= 7; ++age) {
      const double h = 2.0 * (age + 1);
      const std::string model = stem + "_stage" + std::to_string(age);
      out.push_back(
          file("model", model,
               Json{{"ambientocclusion", false},
                    {"textures", {{"particle", block(stem)}, {"stem", block(stem)}}},
                    {"elements", Json::array({turnedBox({0, 0, 8}, {16, h, 8}, "#stem", "ns", 45),
                                              turnedBox({8, 0, 0}, {8, h, 16}, "#stem", "we", 45)})}}));
    }
    addByValue(
        stem, "age", numbers(0, 7), [&](const std::string& age) { return stem + "_stage" + age; }, out);
    const std::string attached = "attached_" + stem;
    out.push_back(file("model", attached,
                       elementModel(Json{{"stem", block(attached)}},
                                    Json::array({box({0, 0, 8}, {16, 16, 8}, "#stem", "ns")}))));
    // Made reaching west; Minecraft's facing is toward the fruit.
    constexpr std::array<std::pair<const char*, int>, 4> kTurn = {
        {{"west", 0}, {"north", 90}, {"east", 180}, {"south", 270}}};
    Json variants;
    for (const auto& [facing, y] : kTurn) variants[std::string("facing=") + facing] = variant(attached, 0, y);
    out.push_back(file("blockstates", attached, Json{{"variants", variants}}));
  }
}

// Two cells tall: a cross of `<texture>_bottom` below and `<texture>_top` above.
void addDoublePlant(const std::string& name, const std::string& texture, bool tinted,
                    std::vector<GeneratedFile>& out) {
  addCross(name + "_bottom", texture + "_bottom", out, tinted);
  addCross(name + "_top", texture + "_top", out, tinted);
  addByValue(
      name, "half", {"lower", "upper"},
      [&](const std::string& half) { return name + (half == "lower" ? "_bottom" : "_top"); }, out);
}

// The sunflower: a double plant whose top holds its flower head, leaning east, its face on that side.
void addSunflower(std::vector<GeneratedFile>& out) {
  addCross("sunflower_bottom", "sunflower_bottom", out);
  Json head = box({9.6, 0, 1}, {9.6, 16, 15}, "#back", "w");
  head["faces"]["east"] = Json{{"texture", "#front"}};
  head["rotation"] = Json{{"origin", {8, 8, 8}}, {"axis", "z"}, {"angle", 22.5}, {"rescale", true}};
  Json elements = Json::array({turnedBox({0.8, 0, 8}, {15.2, 8, 8}, "#cross", "ns", 45),
                               turnedBox({8, 0, 0.8}, {8, 8, 15.2}, "#cross", "we", 45), head});
  out.push_back(file("model", "sunflower_top",
                     Json{{"ambientocclusion", false},
                          {"textures",
                           {{"particle", block("sunflower_front")},
                            {"cross", block("sunflower_top")},
                            {"front", block("sunflower_front")},
                            {"back", block("sunflower_back")}}},
                          {"elements", elements}}));
  addByValue(
      "sunflower", "half", {"lower", "upper"},
      [](const std::string& half) { return half == "lower" ? "sunflower_bottom" : "sunflower_top"; }, out);
}

// Growths on a block's faces (vines, lichen, sculk veins, resin): a sheet against each face they hold.
void addMultiface(const std::string& name, bool withDown, bool tinted, std::vector<GeneratedFile>& out) {
  const auto sheet = [&](const std::string& model, std::array<double, 3> from, std::array<double, 3> to,
                         const char* faces) {
    Json e = box(from, to, "#face", faces);
    for (auto& [n, face] : e["faces"].items()) {
      face.erase("cullface");
      if (tinted) face["tintindex"] = 0;
    }
    out.push_back(file("model", model,
                       Json{{"ambientocclusion", false},
                            {"textures", {{"particle", block(name)}, {"face", block(name)}}},
                            {"elements", {e}}}));
  };
  sheet(name, {0, 0, 0.8}, {16, 16, 0.8}, "ns");
  sheet(name + "_up", {0, 15.2, 0}, {16, 15.2, 16}, "du");
  sheet(name + "_down", {0, 0.8, 0}, {16, 0.8, 16}, "du");
  Json parts = Json::array();
  for (const auto& [side, y] : kFacings)
    parts.push_back(Json{{"when", {{side, "true"}}}, {"apply", variant(name, 0, y)}});
  parts.push_back(Json{{"when", {{"up", "true"}}}, {"apply", variant(name + "_up")}});
  if (withDown) parts.push_back(Json{{"when", {{"down", "true"}}}, {"apply", variant(name + "_down")}});
  out.push_back(file("blockstates", name, Json{{"multipart", parts}}));
}

// Mushroom blocks as Minecraft builds them: each face its outside where the property says so, the
// inside texture elsewhere.
void addMushroomBlocks(std::vector<GeneratedFile>& out) {
  for (const char* texture :
       {"brown_mushroom_block", "red_mushroom_block", "mushroom_stem", "mushroom_block_inside"}) {
    out.push_back(file("model", texture,
                       elementModel(Json{{"face", block(texture)}},
                                    Json::array({box({0, 0, 0}, {16, 16, 16}, "#face", "n")}))));
  }
  constexpr std::array<std::tuple<const char*, int, int>, 6> kFaces = {{{"north", 0, 0},
                                                                        {"east", 0, 90},
                                                                        {"south", 0, 180},
                                                                        {"west", 0, 270},
                                                                        {"up", 270, 0},
                                                                        {"down", 90, 0}}};
  for (const char* name : {"brown_mushroom_block", "red_mushroom_block", "mushroom_stem"}) {
    Json parts = Json::array();
    for (const auto& [face, x, y] : kFaces) {
      for (const bool outside : {true, false}) {
        Json apply = variant(outside ? name : "mushroom_block_inside", x, y);
        apply["uvlock"] = true;
        parts.push_back(Json{{"when", {{face, outside ? "true" : "false"}}}, {"apply", apply}});
      }
    }
    out.push_back(file("blockstates", name, Json{{"multipart", parts}}));
  }
}

// Coral, living and dead: a cross, a fan (a low cross) and a fan leaning out from a wall.
void addCorals(std::vector<GeneratedFile>& out) {
  for (const char* kind : {"tube", "brain", "bubble", "fire", "horn"}) {
    for (const std::string dead : {"", "dead_"}) {
      const std::string coral = dead + kind + "_coral", fan = coral + "_fan";
      addCrossBlock(coral, out);
      addModelBlock(fan,
                    Json{{"ambientocclusion", false},
                         {"textures", {{"particle", block(fan)}, {"fan", block(fan)}}},
                         {"elements", Json::array({turnedBox({0, 0, 8}, {16, 8, 8}, "#fan", "ns", 45),
                                                   turnedBox({8, 0, 0}, {8, 8, 16}, "#fan", "we", 45)})}},
                    out);
      Json sheet = box({0, 8, 0}, {16, 8, 16}, "#fan", "du");
      sheet["rotation"] = Json{{"origin", {8, 8, 16}}, {"axis", "x"}, {"angle", 22.5}};
      const std::string wall = dead + kind + "_coral_wall_fan";
      out.push_back(file("model", wall,
                         Json{{"ambientocclusion", false},
                              {"textures", {{"particle", block(fan)}, {"fan", block(fan)}}},
                              {"elements", {sheet}}}));
      out.push_back(file("blockstates", wall,
                         Json{{"variants", facingVariants([&](const std::string&) { return wall; })}}));
    }
  }
}

// Small things in counts: one to four boxes of a texture; where `looks` names textures, a second
// property `lookProperty` (0, 1, 2...) picks among them (a turtle egg's cracks).
void addCounted(const std::string& name, const std::string& property,
                const std::vector<std::array<double, 6>>& boxes, std::vector<GeneratedFile>& out,
                const std::string& lookProperty = "", const std::vector<std::string>& looks = {}) {
  const std::vector<std::string> textures = looks.empty() ? std::vector<std::string>{name} : looks;
  Json variants;
  for (std::size_t k = 0; k < textures.size(); ++k) {
    for (std::size_t n = 1; n <= boxes.size(); ++n) {
      Json elements = Json::array();
      for (std::size_t i = 0; i < n; ++i)
        elements.push_back(
            box({boxes[i][0], boxes[i][1], boxes[i][2]}, {boxes[i][3], boxes[i][4], boxes[i][5]}, "#all"));
      std::string model = name;
      model.append("_").append(std::to_string(n));
      if (k > 0) model.append("_").append(std::to_string(k));
      out.push_back(file("model", model, elementModel(Json{{"all", block(textures[k])}}, elements)));
      std::string key = property;
      key.append("=").append(std::to_string(n));
      if (!looks.empty()) key.append(",").append(lookProperty).append("=").append(std::to_string(k));
      variants[key] = variant(model);
    }
  }
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// Petals, wildflowers and leaf litter: one to four quarters of a sheet on the ground.
void addFlowerbed(const std::string& name, const std::string& property, std::vector<GeneratedFile>& out) {
  constexpr std::array<std::array<double, 2>, 4> kQuarters = {{{0, 0}, {8, 0}, {8, 8}, {0, 8}}};
  Json variants;
  for (int n = 1; n <= 4; ++n) {
    Json elements = Json::array();
    for (int i = 0; i < n; ++i) {
      const auto& q = kQuarters[static_cast<std::size_t>(i)];
      elements.push_back(box({q[0], 1.5, q[1]}, {q[0] + 8, 1.5, q[1] + 8}, "#flower", "du"));
    }
    const std::string model = name + "_" + std::to_string(n);
    out.push_back(file("model", model, elementModel(Json{{"flower", block(name)}}, elements)));
    variants.update(
        facingVariants([&](const std::string&) { return model; }, property + "=" + std::to_string(n) + ","));
  }
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

void addCaveGrowth(std::vector<GeneratedFile>& out) {
  for (const char* thickness : {"tip_merge", "tip", "frustum", "middle", "base"}) {
    for (const char* direction : {"up", "down"})
      addCross(std::string("pointed_dripstone_") + direction + "_" + thickness,
               std::string("pointed_dripstone_") + direction + "_" + thickness, out);
  }
  Json dripstone;
  for (const char* thickness : {"tip_merge", "tip", "frustum", "middle", "base"})
    for (const char* direction : {"up", "down"})
      dripstone[std::string("thickness=") + thickness + ",vertical_direction=" + direction] =
          variant(std::string("pointed_dripstone_") + direction + "_" + thickness);
  out.push_back(file("blockstates", "pointed_dripstone", Json{{"variants", dripstone}}));
  for (const char* bud :
       {"amethyst_cluster", "large_amethyst_bud", "medium_amethyst_bud", "small_amethyst_bud"}) {
    addCross(bud, bud, out);
    out.push_back(file("blockstates", bud, Json{{"variants", pointingVariants(bud)}}));
  }
  for (const char* vine : {"cave_vines", "cave_vines_plant"}) {
    addCross(vine, vine, out);
    addCross(std::string(vine) + "_lit", std::string(vine) + "_lit", out);
    addByValue(
        vine, "berries", {"false", "true"},
        [&](const std::string& b) { return std::string(vine) + (b == "true" ? "_lit" : ""); }, out);
  }
  // Dripleaves: a leaf on a stem; the small one's upper half is its leaves.
  const Json leaf{{"leaf", block("big_dripleaf_top")}, {"stem", block("big_dripleaf_stem")}};
  out.push_back(
      file("model", "big_dripleaf",
           elementModel(leaf, Json::array({box({0, 15, 0}, {16, 15, 16}, "#leaf", "du"),
                                           turnedBox({0.8, 0, 8}, {15.2, 15, 8}, "#stem", "ns", 45),
                                           turnedBox({8, 0, 0.8}, {8, 15, 15.2}, "#stem", "we", 45)}))));
  out.push_back(file("blockstates", "big_dripleaf",
                     Json{{"variants", facingVariants([](const std::string&) { return "big_dripleaf"; })}}));
  addCross("big_dripleaf_stem", "big_dripleaf_stem", out);
  out.push_back(
      file("blockstates", "big_dripleaf_stem",
           Json{{"variants", facingVariants([](const std::string&) { return "big_dripleaf_stem"; })}}));
  out.push_back(
      file("model", "small_dripleaf_top",
           elementModel(leaf, Json::array({box({2, 10, 2}, {14, 10, 14}, "#leaf", "du"),
                                           turnedBox({0.8, 0, 8}, {15.2, 10, 8}, "#stem", "ns", 45)}))));
  Json small = facingVariants([](const std::string&) { return "small_dripleaf_top"; }, "half=upper,");
  small.update(facingVariants([](const std::string&) { return "big_dripleaf_stem"; }, "half=lower,"));
  out.push_back(file("blockstates", "small_dripleaf", Json{{"variants", small}}));
  // Azaleas: a leafy top over a trunk.
  for (const std::string kind : {"azalea", "flowering_azalea"}) {
    addModelBlock(kind,
                  elementModel(Json{{"top", block(kind + "_top")},
                                    {"side", block(kind + "_side")},
                                    {"plant", block("azalea_plant")}},
                               Json::array({box({0, 8, 0}, {16, 16, 16}, "#side", "dnswe"),
                                            box({0, 8, 0}, {16, 16, 16}, "#top", "u"),
                                            turnedBox({0.8, 0, 8}, {15.2, 8, 8}, "#plant", "ns", 45),
                                            turnedBox({8, 0, 0.8}, {8, 8, 15.2}, "#plant", "we", 45)})),
                  out);
  }
  addCross("flowering_azalea_plant", "flowering_azalea_plant", out);
}

void addWaterAndEndPlants(std::vector<GeneratedFile>& out) {
  addCounted("sea_pickle", "pickles",
             {{6, 0, 6, 10, 6, 10}, {3, 0, 3, 7, 6, 7}, {9, 0, 4, 13, 4, 8}, {4, 0, 9, 8, 5, 13}}, out);
  addCounted("turtle_egg", "eggs",
             {{5, 0, 4, 9, 7, 8}, {1, 0, 7, 5, 5, 11}, {10, 0, 9, 14, 4, 13}, {6, 0, 10, 10, 5, 14}}, out,
             "hatch", {"turtle_egg", "turtle_egg_slightly_cracked", "turtle_egg_very_cracked"});
  addModelBlock(
      "sniffer_egg",
      elementModel(Json{{"all", block("sniffer_egg")}}, Json::array({box({1, 0, 2}, {15, 16, 14}, "#all")})),
      out);
  out.push_back(file("model", "dried_ghast",
                     elementModel(Json{{"all", block("dried_ghast")}},
                                  Json::array({box({3, 0, 3}, {13, 10, 13}, "#all")}))));
  out.push_back(file("blockstates", "dried_ghast", single("dried_ghast")));
  for (const char* flat : {"lily_pad", "frogspawn"}) {
    out.push_back(file("model", flat,
                       elementModel(Json{{"all", block(flat)}},
                                    Json::array({box({0, 0.5, 0}, {16, 0.5, 16}, "#all", "du")}))));
    out.push_back(file("blockstates", flat, single(flat)));
  }
  addDoublePlant("tall_seagrass", "tall_seagrass", false, out);
  for (const char* name : {"kelp", "kelp_plant"}) addCrossBlock(name, out);
  // Bamboo: a stalk with leaves when it has them; its sapling is a shoot.
  const Json stalk = box({6.5, 0, 6.5}, {9.5, 16, 9.5}, "#stalk", "dunswe");
  Json variants;
  for (const char* leaves : {"none", "small", "large"}) {
    const std::string model = std::string("bamboo_") + leaves;
    Json elements = Json::array({stalk});
    if (std::string(leaves) != "none") {
      elements.push_back(turnedBox({0.8, 0, 8}, {15.2, 16, 8}, "#leaves", "ns", 45));
      elements.push_back(turnedBox({8, 0, 0.8}, {8, 16, 15.2}, "#leaves", "we", 45));
    }
    out.push_back(file("model", model,
                       elementModel(Json{{"stalk", block("bamboo_stalk")},
                                         {"leaves", block(std::string("bamboo_") + leaves + "_leaves")}},
                                    elements)));
    variants[std::string("leaves=") + leaves] = variant(model);
  }
  out.push_back(file("blockstates", "bamboo", Json{{"variants", variants}}));
  addCross("bamboo_sapling", "bamboo_stage0", out);
  out.push_back(file("blockstates", "bamboo_sapling", single("bamboo_sapling")));
  // Chorus: a core with an arm toward each joined side; its flower a cube, dead at the last age.
  out.push_back(file("model", "chorus_plant",
                     elementModel(Json{{"all", block("chorus_plant")}},
                                  Json::array({box({4, 4, 4}, {12, 12, 12}, "#all")}))));
  out.push_back(file("model", "chorus_plant_side",
                     elementModel(Json{{"all", block("chorus_plant")}},
                                  Json::array({box({4, 4, 0}, {12, 12, 4}, "#all", "dunwe")}))));
  Json parts = Json::array({Json{{"apply", variant("chorus_plant")}}});
  constexpr std::array<std::tuple<const char*, int, int>, 6> kArms = {{{"north", 0, 0},
                                                                       {"east", 0, 90},
                                                                       {"south", 0, 180},
                                                                       {"west", 0, 270},
                                                                       {"up", 270, 0},
                                                                       {"down", 90, 0}}};
  for (const auto& [side, x, y] : kArms)
    parts.push_back(Json{{"when", {{side, "true"}}}, {"apply", variant("chorus_plant_side", x, y)}});
  out.push_back(file("blockstates", "chorus_plant", Json{{"multipart", parts}}));
  for (const char* flower : {"chorus_flower", "chorus_flower_dead"})
    out.push_back(file("model", flower, child("block/cube_all", Json{{"all", block(flower)}})));
  addByValue(
      "chorus_flower", "age", numbers(0, 5),
      [](const std::string& age) { return age == "5" ? "chorus_flower_dead" : "chorus_flower"; }, out);
}

void addCocoa(std::vector<GeneratedFile>& out) {
  constexpr std::array<std::array<double, 3>, 3> kPods = {
      {{4, 5, 12}, {6, 7, 12}, {8, 9, 12}}};  // width, height, top
  Json variants;
  for (int age = 0; age <= 2; ++age) {
    const auto& [w, h, top] = kPods[static_cast<std::size_t>(age)];
    const std::string model = "cocoa_stage" + std::to_string(age);
    out.push_back(
        file("model", model,
             elementModel(Json{{"pod", block(model)}},
                          Json::array({box({8 - w / 2, top - h, 1}, {8 + w / 2, top, 1 + w}, "#pod")}))));
    variants.update(
        facingVariants([&](const std::string&) { return model; }, "age=" + std::to_string(age) + ","));
  }
  out.push_back(file("blockstates", "cocoa", Json{{"variants", variants}}));
}

}  // namespace

void addPlantFiles(std::vector<GeneratedFile>& out) {
  addTemplates(out);
  for (const char* name : {"cobweb", "bush", "short_dry_grass", "tall_dry_grass", "firefly_bush",
                           "cactus_flower", "spore_blossom", "hanging_roots", "mangrove_propagule",
                           "weeping_vines", "weeping_vines_plant", "twisting_vines", "twisting_vines_plant"})
    addCrossBlock(name, out);
  addCrossBlock("sugar_cane", out, true);
  // Fire in two looks, picked per cell, as Minecraft's fire_0 and fire_1.
  for (const std::string fire : {"fire", "soul_fire"}) {
    addCross(fire, fire + "_0", out);
    addCross(fire + "_1", fire + "_1", out);
    out.push_back(file("blockstates", fire,
                       Json{{"variants", {{"", Json::array({variant(fire), variant(fire + "_1")})}}}}));
  }
  addCross("pale_hanging_moss", "pale_hanging_moss", out);
  addCross("pale_hanging_moss_tip", "pale_hanging_moss_tip", out);
  addByValue(
      "pale_hanging_moss", "tip", {"false", "true"},
      [](const std::string& t) { return t == "true" ? "pale_hanging_moss_tip" : "pale_hanging_moss"; }, out);
  addCrops(out);
  for (const char* plant : {"lilac", "rose_bush", "peony", "pitcher_plant"})
    addDoublePlant(plant, plant, false, out);
  addSunflower(out);
  addDoublePlant("tall_grass", "tall_grass", true, out);
  addDoublePlant("large_fern", "large_fern", true, out);
  addCrossBlock("pitcher_crop", out);
  addMultiface("vine", false, true, out);
  for (const char* growth : {"glow_lichen", "sculk_vein", "resin_clump"})
    addMultiface(growth, true, false, out);
  addMushroomBlocks(out);
  addCorals(out);
  addFlowerbed("pink_petals", "flower_amount", out);
  addFlowerbed("wildflowers", "flower_amount", out);
  addFlowerbed("leaf_litter", "segment_amount", out);
  addCaveGrowth(out);
  addWaterAndEndPlants(out);
  addCocoa(out);
  for (const std::string carpet : {"moss", "pale_moss"})
    addModelBlock(carpet + "_carpet", child("block/carpet", Json{{"wool", block(carpet + "_block")}}), out);
}

}  // namespace terrasol::packgen
