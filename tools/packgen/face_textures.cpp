// Textures of the coloured blocks (candles, shulker boxes, glazed terracotta in sixteen colours,
// heads), the fronted blocks of wood and stone (pumpkins, smokers, looms, tables, nests, barrels), and
// Minecraft's own names for work stations' and redstone's faces, so a pack that textures them shows.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <string>

#include "texture_parts.h"

namespace terrasol::packgen {
namespace {

// Glazed terracotta: a bold figure of two colours on a glazed ground, different for each dye.
Texel glazed(int x, int y, std::size_t colour) {
  const glm::vec3 base = dye(colour), light = glm::mix(base, glm::vec3(1.0f), 0.55f), dark = base * 0.55f;
  const float u = x - 7.5f, v = y - 7.5f;
  const float r = std::sqrt(u * u + v * v), a = std::atan2(v, u);
  const float swirl =
      std::sin(a * static_cast<float>(2 + colour % 3) + r * 0.55f + static_cast<float>(colour));
  Texel t;
  t.color = swirl > 0.35f ? light : swirl < -0.45f ? dark : base;
  if (x == 0 || y == 0) t.color = dark;
  t.smoothness = 215;
  t.f0 = 12;
  t.height = swirl > 0.35f ? 1.0f : 0.85f;
  return t;
}

// A shulker box: its colour with a lid seam two-thirds up and a paler lid.
Texel shulker(int x, int y, glm::vec3 colour) {
  Texel t = smooth(x, y, 1341, colour, 0.06f, 150);
  if (y == 5) t.color *= 0.55f, t.height = 0.5f;
  if (y < 5) t.color *= 1.1f;
  return t;
}

// Heads: skin with two eyes and a mouth on the face; `side` is the skin alone.
struct HeadLook {
  const char* name;
  glm::vec3 skin, eyes;
};

Texel headFace(int x, int y, const HeadLook& h, bool face) {
  Texel t = rock(1351, x, y, h.skin, 0.12f);
  if (!face) return t;
  const bool eye = y >= 5 && y <= 7 && ((x >= 3 && x <= 5) || (x >= 10 && x <= 12));
  const bool mouth = y >= 10 && y <= 11 && x >= 5 && x <= 10;
  if (eye || mouth) t.color = h.eyes, t.height = 0.6f;
  return t;
}

Texel candleWax(int x, int y, glm::vec3 colour, bool lit) {
  Texel t = smooth(x, y, 1361, colour, 0.05f, 130);
  if (y < 10) t.color = rgb(40, 35, 30);  // the wick above the wax
  if (lit && y < 10) t.color = rgb(255, 200, 90), t.emission = 254;
  return t;
}

}  // namespace

void addColouredTextures(std::vector<GeneratedTexture>& out) {
  out.push_back(still("shulker_box", [](int x, int y) { return shulker(x, y, rgb(150, 110, 150)); }));
  out.push_back(still("candle", [](int x, int y) { return candleWax(x, y, rgb(230, 210, 160), false); }));
  out.push_back(still("candle_lit", [](int x, int y) { return candleWax(x, y, rgb(230, 210, 160), true); }));
  for (std::size_t i = 0; i < kDyes.size(); ++i) {
    const std::string c = kDyes[i].first;
    const glm::vec3 colour = dye(i);
    out.push_back(still(c + "_shulker_box", [=](int x, int y) { return shulker(x, y, colour); }));
    out.push_back(still(c + "_candle", [=](int x, int y) { return candleWax(x, y, colour, false); }));
    out.push_back(still(c + "_candle_lit", [=](int x, int y) { return candleWax(x, y, colour, true); }));
    out.push_back(still(c + "_glazed_terracotta", [=](int x, int y) { return glazed(x, y, i); }));
  }
  const std::array<HeadLook, 7> heads = {{{"skeleton_skull", rgb(210, 210, 200), rgb(40, 40, 40)},
                                          {"wither_skeleton_skull", rgb(45, 45, 45), rgb(10, 10, 10)},
                                          {"zombie_head", rgb(90, 140, 80), rgb(20, 40, 20)},
                                          {"player_head", rgb(190, 140, 110), rgb(60, 60, 150)},
                                          {"creeper_head", rgb(90, 180, 80), rgb(10, 20, 10)},
                                          {"dragon_head", rgb(35, 30, 40), rgb(200, 60, 220)},
                                          {"piglin_head", rgb(230, 160, 150), rgb(40, 20, 20)}}};
  for (const HeadLook& h : heads) {
    out.push_back(still(h.name, [=](int x, int y) { return headFace(x, y, h, true); }));
    out.push_back(
        still(std::string(h.name) + "_side", [=](int x, int y) { return headFace(x, y, h, false); }));
  }
}

// Fronted blocks of wood and stone: smokers, furnaces, looms, tables, nests, barrels, bookshelves,
// carved pumpkins.
void addFrontTextures(std::vector<GeneratedTexture>& out) {
  const glm::vec3 oak = rgb(162, 130, 78), spruce = rgb(115, 85, 50), darkOak = rgb(70, 50, 30);
  const auto pumpkinFace = [](int x, int y, bool lit) {
    Texel t = rock(1431, x, y, rgb(210, 120, 30), 0.12f);
    const bool eye = y >= 4 && y <= 6 && ((x >= 3 && x <= 5) || (x >= 10 && x <= 12));
    const bool mouth = (y == 10 && x >= 3 && x <= 12) || (y == 11 && x >= 4 && x <= 11 && x % 2 == 0);
    if (eye || mouth) {
      t.color = lit ? rgb(255, 220, 100) : rgb(40, 20, 10);
      t.emission = lit ? 250 : 255;
      t.height = 0.3f;
    }
    return t;
  };
  addAll(
      out,
      {{"carved_pumpkin", [=](int x, int y) { return pumpkinFace(x, y, false); }},
       {"jack_o_lantern", [=](int x, int y) { return pumpkinFace(x, y, true); }},
       {"smoker_front",
        [](int x, int y) { return hole(x, y, 7, 10, 3, framed(x, y, stone(x, y), rgb(70, 55, 40))); }},
       {"smoker_side", [](int x, int y) { return framed(x, y, stone(x, y), rgb(70, 55, 40)); }},
       {"smoker_top",
        [](int x, int y) { return hole(x, y, 7, 7, 2, framed(x, y, stone(x, y), rgb(70, 55, 40))); }},
       {"smoker_bottom", [](int x, int y) { return stone(x, y); }},
       {"blast_furnace_front",
        [](int x, int y) {
          return hole(x, y, 7, 10, 3,
                      framed(x, y, smooth(x, y, 1432, rgb(100, 100, 105), 0.1f, 120), rgb(60, 60, 65)));
        }},
       {"blast_furnace_side",
        [](int x, int y) {
          return framed(x, y, smooth(x, y, 1433, rgb(100, 100, 105), 0.1f, 120), rgb(60, 60, 65));
        }},
       {"blast_furnace_top",
        [](int x, int y) { return chiseled(x, y, smooth(x, y, 1434, rgb(100, 100, 105), 0.1f, 120)); }},
       {"loom_front",
        [=](int x, int y) {
          Texel t = planksOf(x, y, oak);
          if (!rim(x, y, 3) && x % 2 == 0) t.color = rgb(220, 210, 190);  // threads
          return t;
        }},
       {"loom_side", [=](int x, int y) { return framed(x, y, planksOf(x, y, oak), oak * 0.7f); }},
       {"loom_top", [=](int x, int y) { return planksOf(x, y, oak * 1.1f); }},
       {"loom_bottom", [=](int x, int y) { return planksOf(x, y, oak * 0.8f); }},
       {"cartography_table_top",
        [=](int x, int y) {
          Texel t = planksOf(x, y, darkOak);
          if (!rim(x, y, 2))
            t.color = rgb(220, 210, 170) * (0.9f + 0.15f * hash01(1435, x / 3, y / 3));  // the map
          return t;
        }},
       {"cartography_table_side1",
        [=](int x, int y) { return framed(x, y, planksOf(x, y, darkOak), rgb(220, 210, 170)); }},
       {"fletching_table_top",
        [=](int x, int y) { return framed(x, y, planksOf(x, y, rgb(200, 180, 120)), rgb(130, 100, 60)); }},
       {"fletching_table_side",
        [=](int x, int y) {
          Texel t = planksOf(x, y, rgb(200, 180, 120));
          if (x == y || x == 15 - y) t.color = rgb(230, 230, 230);  // feathers
          return t;
        }},
       {"smithing_table_top",
        [](int x, int y) {
          return framed(x, y, metalBlock(x, y, rgb(60, 60, 70), 230, 140), rgb(50, 40, 45));
        }},
       {"smithing_table_side",
        [=](int x, int y) { return framed(x, y, planksOf(x, y, darkOak), rgb(60, 60, 70)); }},
       {"smithing_table_bottom", [=](int x, int y) { return planksOf(x, y, darkOak); }},
       {"chiseled_bookshelf_empty",
        [=](int x, int y) {
          Texel t = planksOf(x, y, oak);
          if (!rim(x, y) && y != 7 && y != 8 && x % 5 != 0) t.color = rgb(40, 28, 18), t.height = 0.2f;
          return t;
        }},
       {"chiseled_bookshelf_side",
        [=](int x, int y) { return framed(x, y, planksOf(x, y, oak), oak * 0.75f); }},
       {"chiseled_bookshelf_top", [=](int x, int y) { return planksOf(x, y, oak); }},
       {"barrel_side",
        [=](int x, int y) {
          Texel t = planksOf(y, x, spruce);
          if (y == 3 || y == 12) t = metalBlock(x, y, rgb(80, 80, 85), 230, 120);
          return t;
        }},
       {"barrel_top",
        [=](int x, int y) {
          return hole(x, y, 7, 7, 1, framed(x, y, planksOf(x, y, spruce), spruce * 0.7f));
        }},
       {"barrel_top_open",
        [=](int x, int y) {
          return rim(x, y, 2) ? planksOf(x, y, spruce) : tinted(clear(), rgb(20, 15, 10));
        }},
       {"barrel_bottom", [=](int x, int y) { return framed(x, y, planksOf(x, y, spruce), spruce * 0.7f); }}});
  for (const std::string kind : {"bee_nest", "beehive"}) {
    const glm::vec3 wood = kind == "bee_nest" ? rgb(200, 160, 70) : rgb(180, 140, 80);
    const auto front = [=](int x, int y, bool honey) {
      Texel t = framed(x, y, planksOf(x, y, wood), wood * 0.75f);
      if (y >= 7 && y <= 9 && x >= 6 && x <= 9) t.color = rgb(30, 20, 10), t.height = 0.2f;
      if (honey && y >= 11 && y <= 13 && x >= 4 && x <= 11) t.color = rgb(240, 170, 30), t.smoothness = 220;
      return t;
    };
    addAll(out, {{kind + "_front", [=](int x, int y) { return front(x, y, false); }},
                 {kind + "_front_honey", [=](int x, int y) { return front(x, y, true); }},
                 {kind + "_side", [=](int x, int y) { return planksOf(y, x, wood); }}});
  }
  addAll(out, {{"bee_nest_top", [](int x, int y) { return rock(1436, x, y, rgb(200, 160, 70), 0.2f); }},
               {"bee_nest_bottom", [](int x, int y) { return rock(1437, x, y, rgb(170, 130, 60), 0.2f); }},
               {"beehive_end", [](int x, int y) {
                  return framed(x, y, planksOf(x, y, rgb(180, 140, 80)), rgb(130, 100, 60));
                }}});
}

// Minecraft's own names for the faces of work stations and redstone parts, so a resource pack that
// textures them shows on them: the furnaces lit, vertical dispensers, conditional command blocks,
// the structure block's modes, lecterns, grindstones, stonecutters, bells, brewing stands, cauldrons,
// composters, hoppers, campfire logs, table fronts.
void addFaceTextures(std::vector<GeneratedTexture>& out) {
  const glm::vec3 oak = rgb(162, 130, 78), darkOak = rgb(70, 50, 30), iron = rgb(80, 80, 85);
  const auto lit = [](int x, int y, const Texel& around) {
    Texel t = hole(x, y, 7, 10, 3, around);
    if (t.height < 0.2f && y >= 9) t.color = rgb(250, 170, 60), t.emission = 240;
    return t;
  };
  const auto log = [](int x, int y, bool burning, glm::vec3 ember) {
    Texel t = logSideOf(x, y, rgb(90, 70, 50));
    if (burning && hash01(1441, x, y) < 0.18f) t.color = ember, t.emission = 220;
    return t;
  };
  addAll(
      out,
      {{"furnace_front_on", [=](int x, int y) { return lit(x, y, cobblestone(x, y)); }},
       {"smoker_front_on",
        [=](int x, int y) { return lit(x, y, framed(x, y, stone(x, y), rgb(70, 55, 40))); }},
       {"blast_furnace_front_on",
        [=](int x, int y) {
          return lit(x, y, framed(x, y, smooth(x, y, 1432, rgb(100, 100, 105), 0.1f, 120), rgb(60, 60, 65)));
        }},
       {"dispenser_front_vertical",
        [](int x, int y) { return hole(x, y, 7, 7, 3, framed(x, y, cobblestone(x, y), rgb(90, 90, 90))); }},
       {"dropper_front_vertical",
        [](int x, int y) { return hole(x, y, 7, 7, 2, framed(x, y, cobblestone(x, y), rgb(90, 90, 90))); }},
       {"observer_top",
        [](int x, int y) {
          Texel t = cobblestone(x, y);
          if (x >= 6 && x <= 9 && y >= 3) t.color = rgb(150, 40, 30), t.height = 0.5f;  // the arrow's shaft
          return t;
        }},
       {"redstone_dust_line1", [](int x, int y) { return dust(y, x, true); }},
       {"crafting_table_front",
        [=](int x, int y) {
          Texel t = planksOf(x, y, oak);
          if (y < 3) t.color *= 0.7f;
          if (x >= 5 && x <= 10 && y >= 6 && y <= 12 && (x + y) % 3 == 0)
            t = metalBlock(x, y, rgb(140, 140, 140), 230, 120);
          return t;
        }},
       {"smithing_table_front",
        [=](int x, int y) { return hole(x, y, 7, 9, 2, framed(x, y, planksOf(x, y, darkOak), iron)); }},
       {"fletching_table_front",
        [=](int x, int y) {
          Texel t = planksOf(x, y, rgb(200, 180, 120));
          if (y == 8 && x > 2 && x < 13) t.color = rgb(230, 230, 230);  // an arrow's shaft
          return t;
        }},
       {"cartography_table_side2",
        [=](int x, int y) { return framed(x, y, planksOf(y, x, darkOak), rgb(200, 190, 150)); }},
       {"cartography_table_side3",
        [=](int x, int y) { return framed(x, y, planksOf(x, y, darkOak * 1.1f), rgb(200, 190, 150)); }},
       {"lectern_top",
        [=](int x, int y) {
          Texel t = planksOf(x, y, oak);
          if (rim(x, y, 2)) t.color *= 0.75f;
          return t;
        }},
       {"lectern_sides", [=](int x, int y) { return framed(x, y, planksOf(y, x, oak), oak * 0.7f); }},
       {"lectern_front", [=](int x, int y) { return planksOf(y, x, oak * 0.9f); }},
       {"lectern_base", [=](int x, int y) { return framed(x, y, planksOf(x, y, oak), oak * 0.7f); }},
       {"grindstone_round", [](int x, int y) { return smooth(x, y, 1442, rgb(140, 140, 140), 0.15f, 60); }},
       {"grindstone_side",
        [](int x, int y) {
          return hole(x, y, 7, 7, 1,
                      framed(x, y, smooth(x, y, 1443, rgb(150, 150, 150), 0.1f, 60), rgb(110, 110, 110)));
        }},
       {"grindstone_pivot", [=](int x, int y) { return planksOf(y, x, darkOak); }},
       {"stonecutter_top",
        [](int x, int y) {
          Texel t = smooth(x, y, 1444, rgb(150, 150, 150), 0.08f, 120);
          if (y >= 7 && y <= 8) t.color = rgb(60, 60, 65), t.height = 0.3f;  // the saw's slot
          return t;
        }},
       {"stonecutter_side",
        [=](int x, int y) {
          return y < 9 ? planksOf(x, y, oak) : smooth(x, y, 1445, rgb(140, 140, 140), 0.08f, 100);
        }},
       {"stonecutter_bottom", [](int x, int y) { return stone(x, y); }},
       {"stonecutter_saw",
        [](int x, int y) {
          const float r = std::hypot(x - 7.5f, y - 16.0f);
          if (r > 8.0f) return clear();
          Texel t = metalBlock(x, y, rgb(190, 190, 195), 230, 200);
          if (r > 7.0f && (x % 2 == 0)) t.color *= 0.7f;  // teeth
          return t;
        }},
       {"bell_top", [](int x, int y) { return metalBlock(x, y, rgb(240, 200, 60), 231, 220); }},
       {"bell_side",
        [](int x, int y) {
          Texel t = metalBlock(x, y, rgb(235, 195, 55), 231, 210);
          if (y == 12) t.color *= 0.75f;  // the rim's band
          return t;
        }},
       {"bell_bottom",
        [](int x, int y) { return hole(x, y, 7, 7, 4, metalBlock(x, y, rgb(220, 180, 50), 231, 200)); }},
       {"brewing_stand",
        [](int x, int y) {
          if (x >= 7 && x <= 8) return metalBlock(x, y, rgb(240, 190, 60), 231, 200);  // the blaze rod
          if (y >= 9 && y <= 14 && (x <= 4 || x >= 11)) {
            Texel t = glass(x, y);  // the bottles
            t.alpha = 0.6f;
            return t;
          }
          return clear();
        }},
       {"brewing_stand_base", [](int x, int y) { return smooth(x, y, 1446, rgb(110, 110, 110), 0.1f, 100); }},
       {"cauldron_top",
        [=](int x, int y) { return rim(x, y, 2) ? metalBlock(x, y, rgb(60, 60, 65), 230, 130) : clear(); }},
       {"cauldron_inner", [=](int x, int y) { return metalBlock(x, y, rgb(45, 45, 50), 230, 110); }},
       {"cauldron_bottom",
        [=](int x, int y) { return hole(x, y, 7, 7, 3, metalBlock(x, y, rgb(55, 55, 60), 230, 120)); }},
       {"composter_top", [=](int x, int y) { return rim(x, y, 2) ? planksOf(x, y, oak) : clear(); }},
       {"composter_side", [=](int x, int y) { return framed(x, y, planksOf(y, x, oak), oak * 0.7f); }},
       {"composter_bottom", [=](int x, int y) { return planksOf(x, y, oak * 0.85f); }},
       {"hopper_top",
        [=](int x, int y) { return rim(x, y, 2) ? metalBlock(x, y, iron, 230, 140) : clear(); }},
       {"hopper_inside", [=](int x, int y) { return metalBlock(x, y, iron * 0.7f, 230, 110); }},
       {"enchanting_table_side",
        [](int x, int y) {
          Texel t = rock(1447, x, y, rgb(30, 20, 45), 0.25f);
          if (y < 4) t.color = rgb(170, 30, 40);  // the cloth hanging over
          return t;
        }},
       {"enchanting_table_bottom", [](int x, int y) { return rock(1448, x, y, rgb(25, 18, 40), 0.25f); }},
       {"campfire_log", [=](int x, int y) { return log(x, y, false, {}); }},
       {"campfire_log_lit", [=](int x, int y) { return log(x, y, true, rgb(250, 150, 40)); }},
       {"soul_campfire_log_lit", [=](int x, int y) { return log(x, y, true, rgb(90, 220, 235)); }},
       {"jigsaw_top", [](int x, int y) { return sign(x, y, rgb(80, 60, 80), rgb(230, 180, 60), kArrow); }},
       {"jigsaw_side", [](int x, int y) { return sign(x, y, rgb(80, 60, 80), rgb(230, 180, 60), kPlain); }},
       {"jigsaw_bottom", [](int x, int y) { return sign(x, y, rgb(70, 50, 70), rgb(230, 180, 60), kRing); }},
       {"sunflower_front",
        [](int x, int y) {
          const float r = std::hypot(x - 7.5f, y - 7.5f);
          if (r > 7.5f) return clear();
          Texel t = rock(1449, x, y, r < 3.5f ? rgb(90, 60, 30) : rgb(250, 200, 30), 0.1f);
          t.porosity = 120;
          return t;
        }},
       {"sunflower_back",
        [](int x, int y) {
          const float r = std::hypot(x - 7.5f, y - 7.5f);
          return r > 7.5f ? clear() : rock(1450, x, y, rgb(70, 130, 40), 0.15f);
        }},
       {"cactus_bottom", [](int x, int y) { return rock(1451, x, y, rgb(120, 150, 80), 0.15f); }}});
  for (int charges = 1; charges <= 3; ++charges) {
    out.push_back(still("respawn_anchor_side" + std::to_string(charges), [=](int x, int y) {
      Texel t = framed(x, y, rock(1419, x, y, rgb(30, 25, 40), 0.2f), rgb(60, 50, 70));
      if (y >= 2 && y <= 3 && x % 4 == 2 && x / 4 < charges) t.color = rgb(200, 120, 255), t.emission = 220;
      return t;
    }));
  }
  for (const std::string kind : {"command_block", "repeating_command_block", "chain_command_block"}) {
    const glm::vec3 base = kind == "command_block"             ? rgb(190, 130, 90)
                           : kind == "repeating_command_block" ? rgb(120, 90, 190)
                                                               : rgb(110, 170, 150);
    out.push_back(still(kind + "_conditional", [=](int x, int y) {
      Texel t = sign(x, y, base, rgb(30, 30, 30), kArrow);
      if (y >= 12 && x >= 6 && x <= 9) t.color = rgb(240, 240, 240);  // the condition's mark
      return t;
    }));
  }
  for (const auto& [mode, ink] :
       std::array<std::pair<const char*, glm::vec3>, 4>{{{"save", rgb(90, 170, 230)},
                                                         {"load", rgb(230, 170, 60)},
                                                         {"corner", rgb(230, 230, 230)},
                                                         {"data", rgb(120, 220, 120)}}}) {
    const glm::vec3 c = ink;
    out.push_back(still(std::string("structure_block_") + mode,
                        [=](int x, int y) { return sign(x, y, rgb(90, 70, 90), c, kRing); }));
  }
  for (const auto& [name, cracks] : std::array<std::pair<const char*, float>, 2>{
           {{"turtle_egg_slightly_cracked", 0.1f}, {"turtle_egg_very_cracked", 0.25f}}}) {
    const float amount = cracks;
    out.push_back(still(name, [=](int x, int y) {
      Texel t = smooth(x, y, 1623, rgb(230, 225, 200), 0.05f, 120);
      if (hash01(1624, x, y) < 0.15f) t.color = rgb(90, 150, 90);
      if (hash01(1452, x / 2, y) < amount) t.color *= 0.4f, t.height = 0.3f;
      return t;
    }));
  }
}

}  // namespace terrasol::packgen
