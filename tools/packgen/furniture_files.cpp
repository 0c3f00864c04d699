// The blocks Minecraft draws with a block-entity renderer, as static models of their usual look: beds,
// chests, signs and hanging signs, banners, heads and skulls, shulker boxes, shelves, decorated pots
// and copper golem statues. Built from the pack's own textures (wool, planks, metals), so a pack that
// retextures those retextures these.

#include <array>
#include <string>

#include "block_files.h"
#include "recipes.h"

namespace terrasol::packgen {
namespace {

// The woods with signs, shelves and hanging signs, each drawn from its planks.
constexpr const char* kSignWoods[] = {"oak",      "spruce",   "birch",    "jungle", "acacia",  "cherry",
                                      "dark_oak", "pale_oak", "mangrove", "bamboo", "crimson", "warped"};
// Copper's four ages, their block textures, and the waxed names beside them.
constexpr std::array<std::pair<const char*, const char*>, 4> kCopperAgeTextures = {
    {{"", "copper_block"},
     {"exposed_", "exposed_copper"},
     {"weathered_", "weathered_copper"},
     {"oxidized_", "oxidized_copper"}}};

std::string planks(const std::string& wood) {
  return block(wood + "_planks");
}

// Sixteen rotations (22.5° steps, 0 facing south) as a quarter turn of the blockstate and one of four
// models turned within by -22.5°, 0, 22.5° or 45°: `model(step)` names the model for step -1..2.
Json rotationVariants(const std::function<std::string(int step)>& model, const std::string& prefix = "") {
  Json variants;
  for (int r = 0; r < 16; ++r) {
    const int quarter = (r + 1) / 4;
    Json v{{"model", block(model(r - 4 * quarter))}};
    if (quarter % 4 != 0) v["y"] = 90 * (quarter % 4);
    variants[prefix + "rotation=" + std::to_string(r)] = v;
  }
  return variants;
}

// The four models of a rotated block: `elements(angle)` turned by each step.
void addRotatedModels(const std::string& name, const Json& textures,
                      const std::function<Json(double angle)>& elements, std::vector<GeneratedFile>& out) {
  for (int step = -1; step <= 2; ++step)
    out.push_back(
        file("model", name + "_" + std::to_string(step + 1), elementModel(textures, elements(22.5 * step))));
}
std::string rotatedModel(const std::string& name, int step) {
  return name + "_" + std::to_string(step + 1);
}

// A bed: a mattress of its wool on four plank legs, the head half with a white pillow. Facing is
// toward the head; both halves are drawn facing north and turned.
void addBed(const std::string& colour, std::vector<GeneratedFile>& out) {
  const std::string name = colour + "_bed";
  const Json textures{
      {"wool", block(colour + "_wool")}, {"wood", block("oak_planks")}, {"pillow", block("white_wool")}};
  const auto legs = [](double z0) {
    return Json::array(
        {box({0, 0, z0}, {3, 3, z0 + 3}, "#wood"), box({13, 0, z0}, {16, 3, z0 + 3}, "#wood")});
  };
  Json head = legs(0);
  head.push_back(box({0, 3, 0}, {16, 9, 16}, "#wool"));
  head.push_back(box({2, 9, 1}, {14, 11, 6}, "#pillow", "unswe"));
  Json foot = legs(13);
  foot.push_back(box({0, 3, 0}, {16, 9, 16}, "#wool"));
  out.push_back(file("model", name + "_head", elementModel(textures, head)));
  out.push_back(file("model", name + "_foot", elementModel(textures, foot)));
  Json variants = facingVariants([&](const std::string&) { return name + "_head"; }, "part=head,");
  variants.update(facingVariants([&](const std::string&) { return name + "_foot"; }, "part=foot,"));
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// A chest: a body and lid with a latch on the front (north). A double chest's halves reach across to
// each other: the left half's partner is clockwise from its facing (east of a north-facing chest).
// The ender chest stands alone.
void addChest(const std::string& name, const std::string& body, const std::string& latch,
              std::vector<GeneratedFile>& out, bool pairs = true) {
  const Json textures{{"body", block(body)}, {"latch", block(latch)}};
  const auto chest = [&](double x0, double x1) {
    return Json::array({box({x0, 0, 1}, {x1, 9, 15}, "#body"), box({x0, 9, 1}, {x1, 14, 15}, "#body"),
                        box({7, 7, 0}, {9, 11, 1}, "#latch", "dunswe")});
  };
  out.push_back(file("model", name, elementModel(textures, chest(1, 15))));
  if (!pairs) {
    out.push_back(file("blockstates", name,
                       Json{{"variants", facingVariants([&](const std::string&) { return name; })}}));
    return;
  }
  out.push_back(file("model", name + "_left", elementModel(textures, chest(1, 16))));
  out.push_back(file("model", name + "_right", elementModel(textures, chest(0, 15))));
  Json variants = facingVariants([&](const std::string&) { return name; }, "type=single,");
  variants.update(facingVariants([&](const std::string&) { return name + "_left"; }, "type=left,"));
  variants.update(facingVariants([&](const std::string&) { return name + "_right"; }, "type=right,"));
  out.push_back(file("blockstates", name, Json{{"variants", variants}}));
}

// Signs of a wood: standing on a post in sixteen rotations, on a wall, hanging from chains (attached
// to the block above or not) and hanging from a wall bracket.
void addSigns(const std::string& wood, std::vector<GeneratedFile>& out) {
  const Json textures{{"planks", planks(wood)}, {"chain", block("iron_chain")}};
  const std::string sign = wood + "_sign";
  addRotatedModels(
      sign, textures,
      [](double angle) {
        return Json::array({turnedBox({0, 7, 7.25}, {16, 15, 8.75}, "#planks", "dunswe", angle),
                            box({7.25, 0, 7.25}, {8.75, 7, 8.75}, "#planks", "dnswe")});
      },
      out);
  out.push_back(file("blockstates", sign,
                     Json{{"variants", rotationVariants([&](int s) { return rotatedModel(sign, s); })}}));

  const std::string wall = wood + "_wall_sign";
  out.push_back(file("model", wall,
                     elementModel(textures, Json::array({box({0, 4.5, 14.5}, {16, 12.5, 16}, "#planks")}))));
  out.push_back(file("blockstates", wall,
                     Json{{"variants", facingVariants([&](const std::string&) { return wall; })}}));

  const std::string hanging = wood + "_hanging_sign";
  addRotatedModels(
      hanging, textures,
      [](double angle) {
        return Json::array({turnedBox({1, 0, 7}, {15, 10, 9}, "#planks", "dunswe", angle),
                            turnedBox({3, 10, 8}, {4, 16, 8}, "#chain", "ns", angle),
                            turnedBox({12, 10, 8}, {13, 16, 8}, "#chain", "ns", angle)});
      },
      out);
  out.push_back(file("blockstates", hanging,
                     Json{{"variants", rotationVariants([&](int s) { return rotatedModel(hanging, s); })}}));

  const std::string wallHanging = wood + "_wall_hanging_sign";
  out.push_back(file("model", wallHanging,
                     elementModel(textures, Json::array({box({1, 0, 7}, {15, 10, 9}, "#planks"),
                                                         box({7, 14, 0}, {9, 16, 16}, "#planks"),
                                                         box({3, 10, 8}, {4, 14, 8}, "#chain", "ns"),
                                                         box({12, 10, 8}, {13, 14, 8}, "#chain", "ns")}))));
  out.push_back(file("blockstates", wallHanging,
                     Json{{"variants", facingVariants([&](const std::string&) { return wallHanging; })}}));
}

// A banner of a colour: a flag of its wool on a pole in sixteen rotations, or hanging from a wall;
// a block high, where Minecraft's reaches into the block above (a model here stays in its cell).
void addBanner(const std::string& colour, std::vector<GeneratedFile>& out) {
  const Json textures{{"cloth", block(colour + "_wool")}, {"pole", block("oak_planks")}};
  const std::string name = colour + "_banner";
  addRotatedModels(
      name, textures,
      [](double angle) {
        return Json::array({box({7, 0, 7}, {9, 14, 9}, "#pole", "dnswe"),
                            turnedBox({1, 14, 7}, {15, 16, 9}, "#pole", "dunswe", angle),
                            turnedBox({1, 1, 9}, {15, 14, 10}, "#cloth", "dunswe", angle)});
      },
      out);
  out.push_back(file("blockstates", name,
                     Json{{"variants", rotationVariants([&](int s) { return rotatedModel(name, s); })}}));
  const std::string wall = colour + "_wall_banner";
  out.push_back(file("model", wall,
                     elementModel(textures, Json::array({box({1, 14, 14}, {15, 16, 16}, "#pole"),
                                                         box({1, 0, 13}, {15, 14, 14}, "#cloth")}))));
  out.push_back(file("blockstates", wall,
                     Json{{"variants", facingVariants([&](const std::string&) { return wall; })}}));
}

// Heads and skulls: a box with a face on the front, on the floor in sixteen rotations or on a wall.
struct Head {
  const char* name;  // "skeleton_skull": its wall form is "skeleton_wall_skull"
  const char* wallName;
  std::array<double, 3> size;  // in 1/16
};
constexpr Head kHeads[] = {{"skeleton_skull", "skeleton_wall_skull", {8, 8, 8}},
                           {"wither_skeleton_skull", "wither_skeleton_wall_skull", {8, 8, 8}},
                           {"zombie_head", "zombie_wall_head", {8, 8, 8}},
                           {"player_head", "player_wall_head", {8, 8, 8}},
                           {"creeper_head", "creeper_wall_head", {8, 8, 8}},
                           {"dragon_head", "dragon_wall_head", {12, 10, 12}},
                           {"piglin_head", "piglin_wall_head", {10, 8, 8}}};

void addHead(const Head& h, std::vector<GeneratedFile>& out) {
  const Json textures{{"face", block(h.name)}, {"skin", block(std::string(h.name) + "_side")}};
  const double x0 = 8 - h.size[0] / 2, z0 = 8 - h.size[2] / 2;
  const auto head = [&](double y0, double zFront, double angle) {
    const std::array<double, 3> from{x0, y0, zFront}, to{x0 + h.size[0], y0 + h.size[1], zFront + h.size[2]};
    Json skin = angle == 0 ? box(from, to, "#skin", "duswe") : turnedBox(from, to, "#skin", "duswe", angle);
    Json face = angle == 0 ? box(from, to, "#face", "n") : turnedBox(from, to, "#face", "n", angle);
    return Json::array({skin, face});
  };
  addRotatedModels(
      h.name, textures, [&](double angle) { return head(0, z0, angle); }, out);
  out.push_back(file("blockstates", h.name,
                     Json{{"variants", rotationVariants([&](int s) { return rotatedModel(h.name, s); })}}));
  out.push_back(file("model", h.wallName, elementModel(textures, head(4, 16 - h.size[2], 0))));
  out.push_back(file("blockstates", h.wallName,
                     Json{{"variants", facingVariants([&](const std::string&) { return h.wallName; })}}));
}

// A shelf of a wood on the wall behind it (south of a north-facing one): a back board and two boards.
void addShelf(const std::string& wood, std::vector<GeneratedFile>& out) {
  const std::string name = wood + "_shelf";
  const Json textures{{"planks", planks(wood)}};
  out.push_back(file("model", name,
                     elementModel(textures, Json::array({box({0, 0, 13}, {16, 16, 16}, "#planks"),
                                                         box({0, 0, 8}, {16, 2, 13}, "#planks", "dunwe"),
                                                         box({0, 14, 8}, {16, 16, 13}, "#planks", "dunwe"),
                                                         box({0, 2, 8}, {1, 14, 13}, "#planks", "nwe"),
                                                         box({15, 2, 8}, {16, 14, 13}, "#planks", "nwe")}))));
  out.push_back(file("blockstates", name,
                     Json{{"variants", facingVariants([&](const std::string&) { return name; })}}));
}

// A copper golem statue: body, head and its rod, standing in every pose as it stands.
void addStatue(const std::string& age, const std::string& texture, std::vector<GeneratedFile>& out) {
  const std::string name = age + "copper_golem_statue";
  const Json textures{{"copper", block(texture)}};
  out.push_back(file("model", name,
                     elementModel(textures, Json::array({box({5, 0, 6}, {11, 8, 10}, "#copper"),
                                                         box({4, 8, 4}, {12, 13, 12}, "#copper"),
                                                         box({7, 13, 7}, {9, 16, 9}, "#copper", "unswe")}))));
  for (const std::string& statue : {name, "waxed_" + name}) {
    out.push_back(file("blockstates", statue,
                       Json{{"variants", facingVariants([&](const std::string&) { return name; })}}));
  }
}

}  // namespace

void addFurnitureFiles(std::vector<GeneratedFile>& out) {
  for (const auto& [colour, rgb] : kDyes) {
    addBed(colour, out);
    addBanner(colour, out);
  }
  addChest("chest", "oak_planks", "iron_block", out);
  addChest("trapped_chest", "oak_planks", "redstone_block", out);
  addChest("ender_chest", "obsidian", "end_stone", out, false);
  for (const auto& [age, texture] : kCopperAgeTextures) {
    addChest(std::string(age) + "copper_chest", texture, "iron_block", out);
    addChest("waxed_" + std::string(age) + "copper_chest", texture, "iron_block", out);
    addStatue(age, texture, out);
  }
  for (const char* wood : kSignWoods) {
    addSigns(wood, out);
    addShelf(wood, out);
  }
  for (const Head& h : kHeads) addHead(h, out);
  // Shulker boxes: a cube of the box's own texture, as Minecraft's block model gives for its particle.
  std::vector<std::string> boxes{"shulker_box"};
  for (const auto& [colour, rgb] : kDyes) boxes.push_back(std::string(colour) + "_shulker_box");
  for (const std::string& name : boxes)
    addModelBlock(name, child("block/cube_all", Json{{"all", block(name)}}), out);
  const Json pot{{"clay", block("terracotta")}};
  out.push_back(file("model", "decorated_pot",
                     elementModel(pot, Json::array({box({1, 0, 1}, {15, 12, 15}, "#clay"),
                                                    box({4, 12, 4}, {12, 14, 12}, "#clay", "nswe"),
                                                    box({3, 14, 3}, {13, 16, 13}, "#clay")}))));
  out.push_back(file("blockstates", "decorated_pot",
                     Json{{"variants", facingVariants([](const std::string&) { return "decorated_pot"; })}}));
}

}  // namespace terrasol::packgen
