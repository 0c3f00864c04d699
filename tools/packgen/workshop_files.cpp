// The workshop's small blocks in Minecraft's layout: work stations drawn from boxes (lecterns, anvils,
// grindstones, stonecutters, enchanting tables, brewing stands, cauldrons, composters, hoppers, bells,
// campfires, beacons, conduits, end portal frames, the dragon egg), scaffolding and bubble columns.

#include <array>
#include <string>

#include "block_files.h"

namespace terrasol::packgen {
namespace {

void addFacingBlock(const std::string& name, const Json& model, std::vector<GeneratedFile>& out) {
  out.push_back(file("model", name, model));
  out.push_back(file("blockstates", name,
                     Json{{"variants", facingVariants([&](const std::string&) { return name; })}}));
}

// Four walls and a floor: a cauldron of metal, a composter of planks. Outside faces `#side`, the inner
// ones `#inside`, the rims `#top`, the floor's top `#inside` and its underside `#bottom`.
Json vessel(double floor) {
  const auto wall = [](std::array<double, 3> from, std::array<double, 3> to, const char* inner) {
    std::string outer;
    for (const char c : std::string("nswe"))
      if (c != inner[0]) outer += c;
    return Json::array({box(from, to, "#side", outer), box(from, to, "#inside", inner),
                        box(from, to, "#top", "u"), box(from, to, "#bottom", "d")});
  };
  Json out = Json::array();
  for (const Json& w : {wall({0, floor, 0}, {2, 16, 16}, "e"), wall({14, floor, 0}, {16, 16, 16}, "w"),
                        wall({2, floor, 0}, {14, 16, 2}, "s"), wall({2, floor, 14}, {14, 16, 16}, "n")})
    for (const Json& e : w) out.push_back(e);
  out.push_back(box({2, floor, 2}, {14, floor + 1, 14}, "#inside", "u"));
  out.push_back(box({2, floor, 2}, {14, floor + 1, 14}, "#bottom", "d"));
  return out;
}

void addCauldrons(std::vector<GeneratedFile>& out) {
  const auto textures = [](const std::string& content) {
    return Json{{"particle", block("cauldron_side")}, {"side", block("cauldron_side")},
                {"inside", block("cauldron_inner")},  {"top", block("cauldron_top")},
                {"bottom", block("cauldron_bottom")}, {"content", block(content)}};
  };
  Json shell = vessel(3);
  for (const std::array<double, 2> foot : {std::array<double, 2>{0, 0}, {12, 0}, {0, 12}, {12, 12}})
    shell.push_back(box({foot[0], 0, foot[1]}, {foot[0] + 4, 3, foot[1] + 4}, "#side", "dnswe"));
  addModelBlock("cauldron", elementModel(textures("water_still"), shell), out);
  const auto filled = [&](const std::string& content, double height, bool tinted) {
    Json elements = shell;
    Json surface = box({2, height, 2}, {14, height, 14}, "#content", "u");
    if (tinted) surface["faces"]["up"]["tintindex"] = 0;
    elements.push_back(surface);
    return elementModel(textures(content), elements);
  };
  Json water;
  for (int level = 1; level <= 3; ++level) {
    const std::string model = "water_cauldron_level" + std::to_string(level);
    out.push_back(file("model", model, filled("water_still", 6 + 3 * level, true)));
    water["level=" + std::to_string(level)] = Json{{"model", block(model)}};
  }
  out.push_back(file("blockstates", "water_cauldron", Json{{"variants", water}}));
  addModelBlock("lava_cauldron", filled("lava_still", 15, false), out);
  Json snow;
  for (int level = 1; level <= 3; ++level) {
    const std::string model = "powder_snow_cauldron_level" + std::to_string(level);
    out.push_back(file("model", model, filled("powder_snow", 6 + 3 * level, false)));
    snow["level=" + std::to_string(level)] = Json{{"model", block(model)}};
  }
  out.push_back(file("blockstates", "powder_snow_cauldron", Json{{"variants", snow}}));
}

void addComposter(std::vector<GeneratedFile>& out) {
  Json variants;
  for (int level = 0; level <= 8; ++level) {
    const std::string model = "composter_level" + std::to_string(level);
    Json elements = vessel(0);
    if (level > 0)
      elements.push_back(box({2, 1 + 2.0 * std::min(level, 7), 2}, {14, 1 + 2.0 * std::min(level, 7), 14},
                             level == 8 ? "#ready" : "#compost", "u"));
    out.push_back(file("model", model,
                       elementModel(Json{{"particle", block("composter_side")},
                                         {"side", block("composter_side")},
                                         {"inside", block("composter_bottom")},
                                         {"top", block("composter_top")},
                                         {"bottom", block("composter_bottom")},
                                         {"compost", block("composter_compost")},
                                         {"ready", block("composter_ready")}},
                                    elements)));
    variants["level=" + std::to_string(level)] = Json{{"model", block(model)}};
  }
  out.push_back(file("blockstates", "composter", Json{{"variants", variants}}));
}

void addHopper(std::vector<GeneratedFile>& out) {
  const Json textures{
      {"metal", block("hopper_outside")}, {"top", block("hopper_top")}, {"inside", block("hopper_inside")}};
  const Json bowl = Json::array(
      {box({0, 10, 0}, {16, 16, 16}, "#metal", "dnswe"), box({0, 10, 0}, {16, 16, 16}, "#top", "u"),
       box({2, 11, 2}, {14, 11, 14}, "#inside", "u"), box({4, 4, 4}, {12, 10, 12}, "#metal", "nswe")});
  Json down = bowl, side = bowl;
  down.push_back(box({6, 0, 6}, {10, 4, 10}, "#metal", "dnswe"));
  side.push_back(box({6, 4, 0}, {10, 8, 4}, "#metal", "dunwe"));
  out.push_back(file("model", "hopper", elementModel(textures, down)));
  out.push_back(file("model", "hopper_side", elementModel(textures, side)));
  Json variants = facingVariants([](const std::string&) { return "hopper_side"; });
  variants["facing=down"] = Json{{"model", block("hopper")}};
  out.push_back(file("blockstates", "hopper", Json{{"variants", variants}}));
}

void addWorkStations(std::vector<GeneratedFile>& out) {
  addFacingBlock("lectern",
                 elementModel(Json{{"base", block("lectern_base")},
                                   {"front", block("lectern_front")},
                                   {"sides", block("lectern_sides")},
                                   {"top", block("lectern_top")}},
                              Json::array({box({0, 0, 0}, {16, 2, 16}, "#base"),
                                           box({4, 2, 4}, {12, 13, 12}, "#front", "ns"),
                                           box({4, 2, 4}, {12, 13, 12}, "#sides", "we"),
                                           box({0, 13, 1}, {16, 16, 15}, "#sides", "dnswe"),
                                           box({0, 13, 1}, {16, 16, 15}, "#top", "u")})),
                 out);
  for (const char* anvil : {"anvil", "chipped_anvil", "damaged_anvil"}) {
    addFacingBlock(anvil,
                   elementModel(Json{{"body", block("anvil")}, {"top", block(std::string(anvil) + "_top")}},
                                Json::array({box({2, 0, 2}, {14, 4, 14}, "#body"),
                                             box({4, 4, 3}, {12, 5, 13}, "#body", "nswe"),
                                             box({6, 5, 4}, {10, 10, 12}, "#body", "nswe"),
                                             box({3, 10, 0}, {13, 16, 16}, "#body", "dnswe"),
                                             box({3, 10, 0}, {13, 16, 16}, "#top", "u")})),
                   out);
  }
  const Json grindstone = elementModel(
      Json{{"round", block("grindstone_round")},
           {"side", block("grindstone_side")},
           {"pivot", block("grindstone_pivot")},
           {"leg", block("dark_oak_log")}},
      Json::array(
          {box({4, 4, 2}, {12, 16, 14}, "#round", "dunswe"), box({4, 4, 2}, {12, 16, 14}, "#side", "we"),
           box({3, 7, 6}, {4, 13, 10}, "#pivot", "dunsw"), box({12, 7, 6}, {13, 13, 10}, "#pivot", "dunse"),
           box({2, 0, 6}, {4, 7, 10}, "#leg", "unswe"), box({12, 0, 6}, {14, 7, 10}, "#leg", "unswe")}));
  out.push_back(file("model", "grindstone", grindstone));
  Json grind;
  for (const char* face : {"floor", "wall", "ceiling"})
    grind.update(
        facingVariants([](const std::string&) { return "grindstone"; }, std::string("face=") + face + ","));
  out.push_back(file("blockstates", "grindstone", Json{{"variants", grind}}));
  addFacingBlock("stonecutter",
                 elementModel(Json{{"top", block("stonecutter_top")},
                                   {"side", block("stonecutter_side")},
                                   {"bottom", block("stonecutter_bottom")},
                                   {"saw", block("stonecutter_saw")}},
                              Json::array({box({0, 0, 0}, {16, 9, 16}, "#side", "nswe"),
                                           box({0, 0, 0}, {16, 9, 16}, "#top", "u"),
                                           box({0, 0, 0}, {16, 9, 16}, "#bottom", "d"),
                                           box({1, 9, 8}, {15, 16, 8}, "#saw", "ns")})),
                 out);
  addModelBlock("enchanting_table",
                elementModel(Json{{"side", block("enchanting_table_side")},
                                  {"top", block("enchanting_table_top")},
                                  {"bottom", block("enchanting_table_bottom")}},
                             Json::array({box({0, 0, 0}, {16, 12, 16}, "#side", "nswe"),
                                          box({0, 0, 0}, {16, 12, 16}, "#top", "u"),
                                          box({0, 0, 0}, {16, 12, 16}, "#bottom", "d")})),
                out);
  addModelBlock(
      "brewing_stand",
      elementModel(
          Json{{"base", block("brewing_stand_base")}, {"stand", block("brewing_stand")}},
          Json::array({box({9, 0, 5}, {15, 2, 11}, "#base"), box({2, 0, 1}, {8, 2, 7}, "#base"),
                       box({2, 0, 9}, {8, 2, 15}, "#base"), box({7, 0, 7}, {9, 14, 9}, "#stand", "unswe"),
                       box({0, 0, 8}, {16, 16, 8}, "#stand", "ns")})),
      out);
  addCauldrons(out);
  addComposter(out);
  addHopper(out);
  const Json bell =
      Json::array({box({5, 5, 5}, {11, 12, 11}, "#side", "nswe"), box({5, 5, 5}, {11, 12, 11}, "#top", "u"),
                   box({4, 4, 4}, {12, 5, 12}, "#side", "nswe"), box({4, 4, 4}, {12, 5, 12}, "#bottom", "du"),
                   box({2, 13, 7}, {14, 15, 9}, "#bar", "dunswe")});
  Json floorBell = bell;
  floorBell.push_back(box({0, 0, 6}, {2, 16, 10}, "#post"));
  floorBell.push_back(box({14, 0, 6}, {16, 16, 10}, "#post"));
  Json hangingBell = bell;
  hangingBell.push_back(box({7, 15, 7}, {9, 16, 9}, "#bar", "unswe"));
  const Json bellTextures{{"particle", block("bell_side")},  {"side", block("bell_side")},
                          {"top", block("bell_top")},        {"bottom", block("bell_bottom")},
                          {"bar", block("dark_oak_planks")}, {"post", block("stone")}};
  out.push_back(file("model", "bell_floor", elementModel(bellTextures, floorBell)));
  out.push_back(file("model", "bell_ceiling", elementModel(bellTextures, hangingBell)));
  Json bells = facingVariants([](const std::string&) { return "bell_floor"; }, "attachment=floor,");
  for (const char* hung : {"ceiling", "single_wall", "double_wall"})
    bells.update(facingVariants([](const std::string&) { return "bell_ceiling"; },
                                std::string("attachment=") + hung + ","));
  out.push_back(file("blockstates", "bell", Json{{"variants", bells}}));
}

// Campfires: four logs, glowing and with two crossed sheets of flame while lit.
void addCampfire(const std::string& name, const std::string& fire, const std::string& litLog,
                 std::vector<GeneratedFile>& out) {
  const Json logs = Json::array({box({1, 0, 0}, {5, 4, 16}, "#log"), box({11, 0, 0}, {15, 4, 16}, "#log"),
                                 box({0, 3, 11}, {16, 7, 15}, "#log"), box({0, 3, 1}, {16, 7, 5}, "#log")});
  Json lit = logs;
  lit.push_back(turnedBox({0.8, 0, 8}, {15.2, 16, 8}, "#fire", "ns", 45));
  lit.push_back(turnedBox({8, 0, 0.8}, {8, 16, 15.2}, "#fire", "we", 45));
  out.push_back(file("model", name, elementModel(Json{{"log", block(litLog)}, {"fire", block(fire)}}, lit)));
  out.push_back(file("model", name + "_off", elementModel(Json{{"log", block("campfire_log")}}, logs)));
  Json variants = facingVariants([&](const std::string&) { return name; }, "lit=true,");
  variants.update(facingVariants([&](const std::string&) { return name + "_off"; }, "lit=false,"));
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// Scaffolding: a plank top on four posts with braces; unstable (not held from below) it has a bottom
// frame too.
void addScaffolding(std::vector<GeneratedFile>& out) {
  const Json textures{{"top", block("scaffolding_top")},
                      {"side", block("scaffolding_side")},
                      {"bottom", block("scaffolding_bottom")}};
  Json stable = Json::array(
      {box({0, 14, 0}, {16, 16, 16}, "#top", "u"), box({0, 14, 0}, {16, 16, 16}, "#side", "dnswe")});
  for (const std::array<double, 2> post : {std::array<double, 2>{0, 0}, {14, 0}, {0, 14}, {14, 14}})
    stable.push_back(box({post[0], 0, post[1]}, {post[0] + 2, 14, post[1] + 2}, "#side", "dnswe"));
  Json unstable = stable;
  unstable.push_back(box({0, 0, 0}, {16, 2, 16}, "#bottom", "du"));
  out.push_back(file("model", "scaffolding_stable", elementModel(textures, stable)));
  out.push_back(file("model", "scaffolding_unstable", elementModel(textures, unstable)));
  out.push_back(file("blockstates", "scaffolding",
                     Json{{"variants",
                           {{"bottom=false", {{"model", block("scaffolding_stable")}}},
                            {"bottom=true", {{"model", block("scaffolding_unstable")}}}}}}));
}

void addEndBlocks(std::vector<GeneratedFile>& out) {
  const Json frame{{"top", block("end_portal_frame_top")},
                   {"side", block("end_portal_frame_side")},
                   {"bottom", block("end_stone")},
                   {"eye", block("end_portal_frame_eye")}};
  const Json base =
      Json::array({box({0, 0, 0}, {16, 13, 16}, "#side", "nswe"), box({0, 0, 0}, {16, 13, 16}, "#top", "u"),
                   box({0, 0, 0}, {16, 13, 16}, "#bottom", "d")});
  Json withEye = base;
  withEye.push_back(box({4, 13, 4}, {12, 16, 12}, "#eye", "unswe"));
  out.push_back(file("model", "end_portal_frame", elementModel(frame, base)));
  out.push_back(file("model", "end_portal_frame_filled", elementModel(frame, withEye)));
  Json variants = facingVariants([](const std::string&) { return "end_portal_frame"; }, "eye=false,");
  variants.update(facingVariants([](const std::string&) { return "end_portal_frame_filled"; }, "eye=true,"));
  out.push_back(file("blockstates", "end_portal_frame", Json{{"variants", variants}}));
  Json egg = Json::array();
  constexpr std::array<std::array<double, 3>, 8> kTiers = {
      {{3, 0, 1}, {2, 1, 3}, {1, 3, 8}, {2, 8, 11}, {3, 11, 13}, {4, 13, 14}, {5, 14, 15}, {6, 15, 16}}};
  for (const auto& [inset, y0, y1] : kTiers)
    egg.push_back(box({inset, y0, inset}, {16 - inset, y1, 16 - inset}, "#egg"));
  addModelBlock("dragon_egg", elementModel(Json{{"egg", block("dragon_egg")}}, egg), out);
  addModelBlock(
      "beacon",
      elementModel(
          Json{{"glass", block("glass")}, {"base", block("obsidian")}, {"core", block("beacon")}},
          Json::array({box({0, 0, 0}, {16, 16, 16}, "#glass"), box({2, 0.1, 2}, {14, 3, 14}, "#base"),
                       box({3, 3, 3}, {13, 14, 13}, "#core")})),
      out);
  addModelBlock(
      "conduit",
      elementModel(Json{{"shell", block("conduit")}}, Json::array({box({5, 5, 5}, {11, 11, 11}, "#shell")})),
      out);
  addModelBlock(
      "heavy_core",
      elementModel(Json{{"core", block("heavy_core")}}, Json::array({box({4, 0, 4}, {12, 8, 12}, "#core")})),
      out);
}

}  // namespace

void addWorkshopFiles(std::vector<GeneratedFile>& out) {
  addWorkStations(out);
  addCampfire("campfire", "campfire_fire", "campfire_log_lit", out);
  addCampfire("soul_campfire", "soul_campfire_fire", "soul_campfire_log_lit", out);
  addEndBlocks(out);
  addScaffolding(out);
  // A bubble column is water with bubbles rising: no model of its own, its water drawn as water.
  out.push_back(file("model", "bubble_column", Json{{"textures", {{"particle", block("water_still")}}}}));
  out.push_back(file("blockstates", "bubble_column", single("bubble_column")));
}

}  // namespace terrasol::packgen
