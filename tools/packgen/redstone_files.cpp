// Redstone's blocks in Minecraft's layout, drawn in each of their states (their behaviour is not
// simulated): buttons and levers, rails, dust, torches, repeaters and comparators, daylight detectors,
// tripwire, pistons, dispensers, droppers and observers, lamps and copper bulbs, sculk sensors, note
// blocks, TNT, targets, and the operator's command, structure and test blocks.

#include <array>
#include <string>

#include "block_files.h"

namespace terrasol::packgen {
namespace {

// Minecraft's attachment of buttons and levers: on the floor, a wall (the model turned onto it) or
// the ceiling, facing one of four ways.
Json attachedVariants(const std::string& model, const std::string& pressed, const char* property) {
  Json variants;
  constexpr std::array<std::pair<const char*, int>, 4> kTurn = {
      {{"north", 0}, {"east", 90}, {"south", 180}, {"west", 270}}};
  for (const char* face : {"floor", "wall", "ceiling"}) {
    for (const auto& [facing, y] : kTurn) {
      for (const bool on : {false, true}) {
        const std::string face_s = face;
        const int x = face_s == "floor" ? 0 : face_s == "wall" ? 90 : 180;
        const int turn = face_s == "ceiling" ? (y + 180) % 360 : y;
        Json v = variant(on ? pressed : model, x, turn);
        if (face_s == "wall") v["uvlock"] = true;
        variants[std::string("face=") + face + ",facing=" + facing + "," + property + "=" +
                 (on ? "true" : "false")] = v;
      }
    }
  }
  return variants;
}

void addButton(const std::string& name, const std::string& texture, std::vector<GeneratedFile>& out) {
  const Json textures{{"texture", block(texture)}};
  out.push_back(
      file("model", name, elementModel(textures, Json::array({box({5, 0, 6}, {11, 2, 10}, "#texture")}))));
  out.push_back(file("model", name + "_pressed",
                     elementModel(textures, Json::array({box({5, 0, 6}, {11, 1, 10}, "#texture")}))));
  out.push_back(
      file("blockstates", name, Json{{"variants", attachedVariants(name, name + "_pressed", "powered")}}));
}

void addLever(std::vector<GeneratedFile>& out) {
  const Json textures{{"base", block("cobblestone")}, {"handle", block("lever")}};
  const auto lever = [&](double angle) {
    Json handle = box({7, 1, 7}, {9, 11, 9}, "#handle", "unswe");
    handle["rotation"] = Json{{"origin", {8, 1, 8}}, {"axis", "x"}, {"angle", number(angle)}};
    return elementModel(textures, Json::array({box({5, 0, 4}, {11, 3, 12}, "#base"), handle}));
  };
  out.push_back(file("model", "lever", lever(-45)));
  out.push_back(file("model", "lever_on", lever(45)));
  out.push_back(
      file("blockstates", "lever", Json{{"variants", attachedVariants("lever", "lever_on", "powered")}}));
}

// Rails: flat, raised toward north or south (turned for east and west), and curved; a plane a
// sixteenth above the ground, as Minecraft lays them.
void addRailTemplates(std::vector<GeneratedFile>& out) {
  const auto plane = [](double angle) {
    Json e{{"from", {0, angle == 0 ? 1 : 9, 0}},
           {"to", {16, angle == 0 ? 1 : 9, 16}},
           {"faces",
            {{"down", {{"uv", {0, 16, 16, 0}}, {"texture", "#rail"}}},
             {"up", {{"uv", {0, 0, 16, 16}}, {"texture", "#rail"}}}}}};
    if (angle != 0)
      e["rotation"] = Json{{"origin", {8, 9, 8}}, {"axis", "x"}, {"angle", angle}, {"rescale", true}};
    return Json{{"ambientocclusion", false}, {"textures", {{"particle", "#rail"}}}, {"elements", {e}}};
  };
  out.push_back(file("model", "rail_flat", plane(0)));
  out.push_back(file("model", "template_rail_raised_ne", plane(45)));
  out.push_back(file("model", "template_rail_raised_sw", plane(-45)));
}

void addRail(const std::string& name, bool curves, bool powered, std::vector<GeneratedFile>& out) {
  Json variants;
  for (const bool on : {false, true}) {
    if (on && !powered) continue;
    const std::string texture = name + (on ? "_on" : ""), model = texture;
    out.push_back(file("model", model, child("block/rail_flat", Json{{"rail", block(texture)}})));
    out.push_back(file("model", model + "_raised_ne",
                       child("block/template_rail_raised_ne", Json{{"rail", block(texture)}})));
    out.push_back(file("model", model + "_raised_sw",
                       child("block/template_rail_raised_sw", Json{{"rail", block(texture)}})));
    const std::string key = powered ? std::string("powered=") + (on ? "true" : "false") + "," : "";
    variants[key + "shape=north_south"] = variant(model);
    variants[key + "shape=east_west"] = variant(model, 0, 90);
    variants[key + "shape=ascending_north"] = variant(model + "_raised_ne");
    variants[key + "shape=ascending_east"] = variant(model + "_raised_ne", 0, 90);
    variants[key + "shape=ascending_south"] = variant(model + "_raised_sw");
    variants[key + "shape=ascending_west"] = variant(model + "_raised_sw", 0, 90);
  }
  if (curves) {
    out.push_back(
        file("model", name + "_corner", child("block/rail_flat", Json{{"rail", block(name + "_corner")}})));
    variants["shape=south_east"] = variant(name + "_corner");
    variants["shape=south_west"] = variant(name + "_corner", 0, 90);
    variants["shape=north_west"] = variant(name + "_corner", 0, 180);
    variants["shape=north_east"] = variant(name + "_corner", 0, 270);
  }
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// Redstone dust: a dot, a line toward each joined side, and up the wall where it climbs.
void addDust(std::vector<GeneratedFile>& out) {
  const Json textures{{"dot", block("redstone_dust_dot")}, {"line", block("redstone_dust_line0")}};
  out.push_back(file("model", "redstone_dust_dot",
                     elementModel(textures, Json::array({box({4, 0.5, 4}, {12, 0.5, 12}, "#dot", "u")}))));
  out.push_back(file("model", "redstone_dust_side",
                     elementModel(textures, Json::array({box({7, 0.5, 0}, {9, 0.5, 8}, "#line", "u")}))));
  out.push_back(file("model", "redstone_dust_side_alt",
                     elementModel(Json{{"line", block("redstone_dust_line1")}},
                                  Json::array({box({7, 0.5, 0}, {9, 0.5, 8}, "#line", "u")}))));
  out.push_back(file("model", "redstone_dust_up",
                     elementModel(textures, Json::array({box({7, 0, 0.5}, {9, 16, 0.5}, "#line", "s")}))));
  Json parts = Json::array({Json{{"apply", {{"model", block("redstone_dust_dot")}}}}});
  for (const auto& [side, y] : kFacings) {
    // Minecraft's second line texture runs east and west.
    const bool alongX = std::string(side) == "east" || std::string(side) == "west";
    parts.push_back(Json{{"when", {{side, "side|up"}}},
                         {"apply", variant(alongX ? "redstone_dust_side_alt" : "redstone_dust_side", 0, y)}});
    parts.push_back(Json{{"when", {{side, "up"}}}, {"apply", variant("redstone_dust_up", 0, y)}});
  }
  out.push_back(file("blockstates", "redstone_wire", Json{{"multipart", parts}}));
}

// Torches on Minecraft's torch templates: standing, and on a wall (the template faces east).
void addTorch(const std::string& name, const std::string& wall, bool lights,
              std::vector<GeneratedFile>& out) {
  Json standing, onWall;
  for (const bool lit : {true, false}) {
    if (!lit && !lights) continue;
    const std::string texture = name + (lit ? "" : "_off");
    out.push_back(file("model", texture, child("block/template_torch", Json{{"torch", block(texture)}})));
    out.push_back(file("model", wall + (lit ? "" : "_off"),
                       child("block/template_torch_wall", Json{{"torch", block(texture)}})));
    const std::string key = lights ? std::string("lit=") + (lit ? "true" : "false") : "";
    standing[key] = variant(texture);
    constexpr std::array<std::pair<const char*, int>, 4> kWall = {
        {{"east", 0}, {"south", 90}, {"west", 180}, {"north", 270}}};
    for (const auto& [facing, y] : kWall)
      onWall[std::string("facing=") + facing + (lights ? "," + key : "")] =
          variant(wall + (lit ? "" : "_off"), 0, y);
  }
  out.push_back(file("blockstates", name, Json{{"variants", standing}}));
  out.push_back(file("blockstates", wall, Json{{"variants", onWall}}));
}

// Repeaters and comparators: a slab of smooth stone showing their top, with their torches.
void addDiode(const std::string& name, const std::string& stateKey, std::vector<GeneratedFile>& out) {
  Json variants;
  for (const bool on : {false, true}) {
    const std::string model = name + (on ? "_on" : "");
    const std::string torch = on ? "redstone_torch" : "redstone_torch_off";
    out.push_back(file(
        "model", model,
        elementModel(Json{{"top", block(model)}, {"slab", block("smooth_stone")}, {"torch", block(torch)}},
                     Json::array({box({0, 0, 0}, {16, 2, 16}, "#slab", "dnswe"),
                                  box({0, 0, 0}, {16, 2, 16}, "#top", "u"),
                                  box({7, 2, 2}, {9, 7, 4}, "#torch", "unswe"),
                                  box({7, 2, 11}, {9, 7, 13}, "#torch", "unswe")}))));
    // Minecraft's repeaters and comparators face away from their output: south is the model's front.
    constexpr std::array<std::pair<const char*, int>, 4> kTurn = {
        {{"south", 0}, {"west", 90}, {"north", 180}, {"east", 270}}};
    for (const auto& [facing, y] : kTurn)
      variants[std::string("facing=") + facing + "," + stateKey + "=" + (on ? "true" : "false")] =
          variant(model, 0, y);
  }
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// A block with a front on the north side, standing in any of six directions: front, back, sides and
// ends (the sides' texture unless `ends` names another).
void addFronted(const std::string& name, const std::string& front, const std::string& side,
                const std::string& back, std::vector<GeneratedFile>& out, const std::string& prefix = "",
                const std::string& ends = "") {
  const std::string end = ends.empty() ? side : ends;
  out.push_back(file("model", name + prefix,
                     child("block/cube", Json{{"particle", block(side)},
                                              {"north", block(front)},
                                              {"south", block(back)},
                                              {"east", block(side)},
                                              {"west", block(side)},
                                              {"up", block(end)},
                                              {"down", block(end)}})));
}

void addPistons(std::vector<GeneratedFile>& out) {
  for (const std::string kind : {"", "sticky_"}) {
    const std::string name = kind + "piston", face = kind.empty() ? "piston_top" : "piston_top_sticky";
    addFronted(name, face, "piston_side", "piston_bottom", out);
    out.push_back(file("model", name + "_base",
                       elementModel(Json{{"side", block("piston_side")},
                                         {"inner", block("piston_inner")},
                                         {"bottom", block("piston_bottom")}},
                                    Json::array({box({0, 0, 4}, {16, 16, 16}, "#side", "duwe"),
                                                 box({0, 0, 4}, {16, 16, 16}, "#inner", "n"),
                                                 box({0, 0, 4}, {16, 16, 16}, "#bottom", "s")}))));
    Json variants = frontVariants(name, "extended=false,");
    variants.update(frontVariants(name + "_base", "extended=true,"));
    out.push_back(file("blockstates", name, Json{{"variants", variants}}));
    const Json head{{"face", block(face)}, {"side", block("piston_side")}};
    out.push_back(file("model", "piston_head" + std::string(kind.empty() ? "" : "_sticky"),
                       elementModel(head, Json::array({box({0, 0, 0}, {16, 16, 4}, "#face", "n"),
                                                       box({0, 0, 0}, {16, 16, 4}, "#side", "duswe"),
                                                       box({6, 6, 4}, {10, 10, 16}, "#side", "duwe")}))));
  }
  Json head = frontVariants("piston_head", "type=normal,");
  head.update(frontVariants("piston_head_sticky", "type=sticky,"));
  out.push_back(file("blockstates", "piston_head", Json{{"variants", head}}));
  out.push_back(file("blockstates", "moving_piston", Json{{"variants", frontVariants("piston_base")}}));
}

void addFrontedBlocks(std::vector<GeneratedFile>& out) {
  // Dispensers and droppers facing up or down show their vertical front, furnace tops round it.
  for (const std::string name : {"dispenser", "dropper"}) {
    addFronted(name, name + "_front", "furnace_side", "furnace_side", out, "", "furnace_top");
    out.push_back(file("model", name + "_vertical",
                       child("block/cube_bottom_top", Json{{"top", block(name + "_front_vertical")},
                                                           {"bottom", block("furnace_top")},
                                                           {"side", block("furnace_top")}})));
    Json variants = frontVariants(name);
    variants["facing=up"] = variant(name + "_vertical");
    variants["facing=down"] = variant(name + "_vertical", 180);
    out.push_back(file("blockstates", name, Json{{"variants", variants}}));
  }
  addFronted("observer", "observer_front", "observer_side", "observer_back", out, "", "observer_top");
  addFronted("observer", "observer_front", "observer_side", "observer_back_on", out, "_on", "observer_top");
  Json observer = frontVariants("observer", "powered=false,");
  observer.update(frontVariants("observer_on", "powered=true,"));
  out.push_back(file("blockstates", "observer", Json{{"variants", observer}}));
  for (const std::string n : {"command_block", "repeating_command_block", "chain_command_block"}) {
    addFronted(n, n + "_front", n + "_side", n + "_back", out);
    addFronted(n, n + "_front", n + "_conditional", n + "_back", out, "_conditional");
    Json variants = frontVariants(n, "conditional=false,");
    variants.update(frontVariants(n + "_conditional", "conditional=true,"));
    out.push_back(file("blockstates", n, Json{{"variants", variants}}));
  }
}

void addCube(const std::string& name, const Json& textures, std::vector<GeneratedFile>& out,
             const std::string& parent = "block/cube_all") {
  out.push_back(file("model", name, child(parent, textures)));
}

void addSwitchedBlocks(std::vector<GeneratedFile>& out) {
  // Lamps and copper bulbs: their texture by lit (and powered) state.
  addCube("redstone_lamp", Json{{"all", block("redstone_lamp")}}, out);
  addCube("redstone_lamp_on", Json{{"all", block("redstone_lamp_on")}}, out);
  out.push_back(
      file("blockstates", "redstone_lamp",
           Json{{"variants",
                 {{"lit=false", variant("redstone_lamp")}, {"lit=true", variant("redstone_lamp_on")}}}}));
  for (const std::string age : kCopperAges) {
    const std::string bulb = age + "copper_bulb";
    Json variants;
    for (const bool lit : {false, true}) {
      for (const bool powered : {false, true}) {
        const std::string model = bulb + (lit ? "_lit" : "") + (powered ? "_powered" : "");
        addCube(model, Json{{"all", block(model)}}, out);
        variants[std::string("lit=") + (lit ? "true" : "false") +
                 ",powered=" + (powered ? "true" : "false")] = variant(model);
      }
    }
    out.push_back(file("blockstates", bulb, Json{{"variants", variants}}));
    out.push_back(file("blockstates", "waxed_" + bulb, Json{{"variants", variants}}));
  }
  addCube("note_block", Json{{"all", block("note_block")}}, out);
  out.push_back(file("blockstates", "note_block", single("note_block")));
  addCube(
      "jukebox",
      Json{{"top", block("jukebox_top")}, {"bottom", block("jukebox_side")}, {"side", block("jukebox_side")}},
      out, "block/cube_bottom_top");
  out.push_back(file("blockstates", "jukebox", single("jukebox")));
  addCube("target", Json{{"end", block("target_top")}, {"side", block("target_side")}}, out,
          "block/cube_column");
  out.push_back(file("blockstates", "target", single("target")));
  addCube("tnt",
          Json{{"top", block("tnt_top")}, {"bottom", block("tnt_bottom")}, {"side", block("tnt_side")}}, out,
          "block/cube_bottom_top");
  out.push_back(file("blockstates", "tnt", single("tnt")));
  for (const char* name : {"test_block", "test_instance_block", "crafter"}) {
    addCube(name, Json{{"all", block(name)}}, out);
    out.push_back(file("blockstates", name, single(name)));
  }
  // The structure block shows its mode; the jigsaw its joint on top.
  Json modes;
  for (const char* mode : {"save", "load", "corner", "data"}) {
    const std::string model = std::string("structure_block_") + mode;
    addCube(model, Json{{"all", block(model)}}, out);
    modes[std::string("mode=") + mode] = variant(model);
  }
  out.push_back(file("blockstates", "structure_block", Json{{"variants", modes}}));
  addCube(
      "jigsaw",
      Json{{"top", block("jigsaw_top")}, {"bottom", block("jigsaw_bottom")}, {"side", block("jigsaw_side")}},
      out, "block/cube_bottom_top");
  out.push_back(file("blockstates", "jigsaw", single("jigsaw")));
}

void addSensors(std::vector<GeneratedFile>& out) {
  addDiode("repeater", "powered", out);
  addDiode("comparator", "powered", out);
  for (const bool inverted : {false, true}) {
    const std::string model = inverted ? "daylight_detector_inverted" : "daylight_detector";
    out.push_back(file("model", model,
                       elementModel(Json{{"top", block(inverted ? "daylight_detector_inverted_top"
                                                                : "daylight_detector_top")},
                                         {"side", block("daylight_detector_side")}},
                                    Json::array({box({0, 0, 0}, {16, 6, 16}, "#side", "dnswe"),
                                                 box({0, 0, 0}, {16, 6, 16}, "#top", "u")}))));
  }
  out.push_back(file("blockstates", "daylight_detector",
                     Json{{"variants",
                           {{"inverted=false", variant("daylight_detector")},
                            {"inverted=true", variant("daylight_detector_inverted")}}}}));
  const Json sensor =
      Json::array({box({0, 0, 0}, {16, 8, 16}, "#side", "dnswe"), box({0, 0, 0}, {16, 8, 16}, "#top", "u"),
                   turnedBox({1, 8, 8}, {7, 16, 8}, "#tendril", "ns", 45),
                   turnedBox({9, 8, 8}, {15, 16, 8}, "#tendril", "ns", -45)});
  out.push_back(file("model", "sculk_sensor",
                     elementModel(Json{{"side", block("sculk")},
                                       {"top", block("sculk_sensor_top")},
                                       {"tendril", block("sculk_sensor_tendril")}},
                                  sensor)));
  out.push_back(file("blockstates", "sculk_sensor", single("sculk_sensor")));
  out.push_back(file("model", "calibrated_sculk_sensor",
                     elementModel(Json{{"side", block("sculk")},
                                       {"top", block("calibrated_sculk_sensor_top")},
                                       {"tendril", block("sculk_sensor_tendril")}},
                                  sensor)));
  out.push_back(
      file("blockstates", "calibrated_sculk_sensor",
           Json{{"variants", facingVariants([](const std::string&) { return "calibrated_sculk_sensor"; })}}));
  out.push_back(file("model", "sculk_shrieker",
                     elementModel(Json{{"side", block("sculk_shrieker_side")},
                                       {"top", block("sculk_shrieker_top")},
                                       {"bottom", block("sculk")}},
                                  Json::array({box({0, 0, 0}, {16, 8, 16}, "#side", "nswe"),
                                               box({0, 0, 0}, {16, 8, 16}, "#top", "u"),
                                               box({0, 0, 0}, {16, 8, 16}, "#bottom", "d")}))));
  out.push_back(file("blockstates", "sculk_shrieker", single("sculk_shrieker")));
  // Tripwire: a thread a sixteenth above the ground joining its hooks.
  out.push_back(file("model", "tripwire_side",
                     elementModel(Json{{"wire", block("tripwire")}},
                                  Json::array({box({7, 1.5, 0}, {9, 1.5, 8}, "#wire", "du")}))));
  Json parts = Json::array();
  for (const auto& [side, y] : kFacings)
    parts.push_back(Json{{"when", {{side, "true"}}}, {"apply", variant("tripwire_side", 0, y)}});
  out.push_back(file("model", "tripwire_knot",
                     elementModel(Json{{"wire", block("tripwire")}},
                                  Json::array({box({7, 1.5, 7}, {9, 1.5, 9}, "#wire", "du")}))));
  parts.push_back(Json{{"apply", variant("tripwire_knot")}});
  out.push_back(file("blockstates", "tripwire", Json{{"multipart", parts}}));
  out.push_back(file("model", "tripwire_hook",
                     elementModel(Json{{"wood", block("oak_planks")}, {"hook", block("tripwire_hook")}},
                                  Json::array({box({6, 1, 14}, {10, 9, 16}, "#wood"),
                                               box({7.5, 5, 8}, {8.5, 6, 14}, "#hook"),
                                               box({6.5, 4, 7}, {9.5, 7, 8}, "#hook")}))));
  out.push_back(file("blockstates", "tripwire_hook",
                     Json{{"variants", facingVariants([](const std::string&) { return "tripwire_hook"; })}}));
}

}  // namespace

void addRedstoneFiles(std::vector<GeneratedFile>& out) {
  for (const char* wood : {"oak", "spruce", "birch", "jungle", "acacia", "cherry", "dark_oak", "pale_oak",
                           "mangrove", "bamboo", "crimson", "warped"})
    addButton(std::string(wood) + "_button", std::string(wood) + "_planks", out);
  addButton("stone_button", "stone", out);
  addButton("polished_blackstone_button", "polished_blackstone", out);
  addLever(out);
  addRailTemplates(out);
  addRail("rail", true, false, out);
  for (const char* rail : {"powered_rail", "detector_rail", "activator_rail"})
    addRail(rail, false, true, out);
  addDust(out);
  addTorch("redstone_torch", "redstone_wall_torch", true, out);
  addTorch("soul_torch", "soul_wall_torch", false, out);
  addTorch("copper_torch", "copper_wall_torch", false, out);
  addPistons(out);
  addFrontedBlocks(out);
  addSwitchedBlocks(out);
  addSensors(out);
}

}  // namespace terrasol::packgen
