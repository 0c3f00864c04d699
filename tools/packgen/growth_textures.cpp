// Textures of growing things: crops by stage, double plants, corals and fans, vines and cave
// growths, dripstone and amethyst, azaleas, bamboo, chorus, cocoa, fire. The natural blocks with faces
// of their own come from natural_textures.cpp.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "texture_parts.h"

namespace terrasol::packgen {
namespace {

Texel leafy(glm::vec3 colour, std::uint64_t seed, int x, int y) {
  Texel t;
  t.color = colour * (0.75f + 0.45f * hash01(seed, x, y));
  t.porosity = 150;
  t.smoothness = 60;
  return t;
}

// Stalks from the ground, `grown` (0..1) of the way up, with `head` at their tops once half grown.
Texel crop(int x, int y, std::uint64_t seed, glm::vec3 stalk, glm::vec3 head, float grown) {
  const float pick = hash01(seed, x, 0);
  if (pick < 0.35f) return clear();
  const int top = 16 - static_cast<int>((0.2f + 0.75f * grown) * 16.0f * (0.8f + 0.2f * pick));
  if (y < top) return clear();
  const bool headHere = grown >= 0.5f && y < top + static_cast<int>(2 + 3 * grown);
  return leafy(headHere ? head : stalk, seed + 1, x, y);
}

// A grown stem bending from the ground toward its fruit (the texture's left).
Texel bentStem(int x, int y, glm::vec3 colour) {
  const float bend = 7.5f - 0.04f * static_cast<float>((15 - y) * (15 - y));
  if (std::abs(static_cast<float>(x) - bend) > 1.2f && !(y == 9 && x > 8 && x < 12)) return clear();
  return leafy(colour, 1523, x, y);
}

// A plant of crossed blades, `tallest` texels high.
Texel blades(int x, int y, std::uint64_t seed, glm::vec3 colour, int tallest) {
  const float blade = hash01(seed, x, 0);
  if (blade < 0.3f || y <= 16 - 3 - static_cast<int>(blade * static_cast<float>(tallest))) return clear();
  return leafy(colour, seed + 1, x, y);
}

// Strands hanging from the top (or rising from the bottom), with `fruit` dots glowing where `lit`.
Texel strands(int x, int y, std::uint64_t seed, glm::vec3 colour, bool rising, glm::vec3 fruit, bool lit) {
  const float pick = hash01(seed, x, 0);
  if (pick < 0.45f || x % 2 == 0) return clear();
  const int length = 6 + static_cast<int>(pick * 10.0f);
  const int along = rising ? 15 - y : y;
  if (along >= length) return clear();
  Texel t = leafy(colour, seed + 1, x, y);
  if (lit && hash01(seed + 2, x, y) < 0.18f) t.color = fruit, t.emission = 240;
  return t;
}

// Blobs of `colour` on nothing: lichen, veins, petals, litter, spawn.
Texel patches(int x, int y, std::uint64_t seed, glm::vec3 colour, float coverage, int cells) {
  const Cells c = voronoi(seed, x, y, cells);
  if (c.d1 > coverage) return clear();
  Texel t = leafy(colour * (0.8f + 0.4f * hash01(seed + 1, c.id, 0)), seed + 2, x, y);
  t.height = 1.0f - c.d1 / coverage * 0.5f;
  return t;
}

// A branching coral or fan of a colour (faded grey when dead).
Texel coralPlant(int x, int y, std::uint64_t seed, glm::vec3 colour, bool fan) {
  const float dx = x - 7.5f, dy = 15.5f - y;
  const bool shape = fan ? (dy > 0 && dx * dx + dy * dy < 64.0f && hash01(seed, x, y) > 0.25f)
                         : (hash01(seed, x, 0) > 0.4f && y > 2 + static_cast<int>(6 * hash01(seed, x, 1)));
  if (!shape) return clear();
  Texel t = leafy(colour, seed + 1, x, y);
  t.porosity = 120;
  return t;
}

// A tapering spike of dripstone: `width` at the widest, narrowing toward its point.
Texel spike(int x, int y, float widthTop, float widthBottom) {
  const float width = widthTop + (widthBottom - widthTop) * (static_cast<float>(y) / 15.0f);
  if (std::abs(x - 7.5f) > width / 2.0f) return clear();
  Texel t = rock(1501, x, y, rgb(135, 105, 85), 0.18f);
  t.porosity = 60;
  return t;
}

Texel crystal(int x, int y, int size) {
  const float dx = std::abs(x - 7.5f), top = 16.0f - static_cast<float>(size);
  if (y < top || dx > (16.0f - y) * 0.45f + 0.5f || (static_cast<int>(dx) % 3 == 2 && y < top + 2))
    return clear();
  Texel t = smooth(x, y, 1502, rgb(170, 110, 220), 0.15f, 220);
  t.emission = 90;
  t.f0 = 30;
  return t;
}

// A side with its top (a soil's top showing on its upper rows) over dirt or netherrack.
Texel flame(int x, int y, std::uint64_t seed, glm::vec3 core, glm::vec3 outer) {
  const float h = 6.0f + 9.0f * hash01(seed, x, 0);
  if (static_cast<float>(15 - y) > h) return clear();
  Texel t;
  t.color = static_cast<float>(15 - y) > h - 3.0f ? core : outer;
  t.emission = 254;
  return t;
}

void addCropTextures(std::vector<GeneratedTexture>& out) {
  const glm::vec3 green = rgb(70, 140, 40);
  for (int s = 0; s <= 7; ++s)
    out.push_back(still("wheat_stage" + std::to_string(s), [=](int x, int y) {
      return crop(x, y, 1511, s < 7 ? green : rgb(190, 170, 70), rgb(220, 190, 90), s / 7.0f);
    }));
  const std::array<std::pair<const char*, glm::vec3>, 3> roots = {
      {{"carrots", rgb(240, 130, 30)}, {"potatoes", rgb(200, 170, 90)}, {"beetroots", rgb(150, 30, 50)}}};
  std::uint64_t seed = 1512;
  for (const auto& [name, fruit] : roots) {
    for (int s = 0; s <= 3; ++s) {
      const glm::vec3 f = fruit;
      const std::uint64_t sd = seed;
      out.push_back(still(std::string(name) + "_stage" + std::to_string(s), [=](int x, int y) {
        Texel t = crop(x, y, sd, green, green * 1.2f, s / 3.0f);
        if (s == 3 && y >= 13 && t.alpha > 0.0f) t.color = f;  // the root shows at the ground
        return t;
      }));
    }
    ++seed;
  }
  for (int s = 0; s <= 2; ++s)
    out.push_back(still("nether_wart_stage" + std::to_string(s), [=](int x, int y) {
      return crop(x, y, 1516, rgb(140, 30, 40), rgb(190, 40, 50), s / 2.0f);
    }));
  for (int s = 0; s <= 1; ++s)
    out.push_back(still("torchflower_crop_stage" + std::to_string(s), [=](int x, int y) {
      return crop(x, y, 1517, rgb(60, 120, 40), rgb(240, 140, 40), 0.3f + 0.3f * s);
    }));
  for (int s = 0; s <= 3; ++s)
    out.push_back(still("sweet_berry_bush_stage" + std::to_string(s), [=](int x, int y) {
      Texel t = blades(x, y, 1518, rgb(50, 100, 50), 4 + 3 * s);
      if (s >= 2 && t.alpha > 0.0f && hash01(1519, x, y) < 0.12f * s) t.color = rgb(200, 30, 40);
      return t;
    }));
  addAll(out, {{"pitcher_crop",
                [](int x, int y) { return crop(x, y, 1520, rgb(80, 130, 90), rgb(90, 150, 200), 0.6f); }},
               {"pumpkin_stem",
                [](int x, int y) { return crop(x, y, 1521, rgb(100, 160, 50), rgb(100, 160, 50), 1.0f); }},
               {"melon_stem",
                [](int x, int y) { return crop(x, y, 1522, rgb(100, 160, 50), rgb(100, 160, 50), 1.0f); }},
               {"attached_pumpkin_stem", [](int x, int y) { return bentStem(x, y, rgb(150, 120, 40)); }},
               {"attached_melon_stem", [](int x, int y) { return bentStem(x, y, rgb(130, 140, 40)); }}});
}

void addPlantTexturesMore(std::vector<GeneratedTexture>& out) {
  const glm::vec3 grey = glm::vec3(0.62f), green = rgb(70, 130, 40), dry = rgb(190, 160, 90);
  addAll(
      out,
      {{"bush", [=](int x, int y) { return blades(x, y, 1531, rgb(60, 110, 40), 10); }},
       {"short_dry_grass", [=](int x, int y) { return blades(x, y, 1532, dry, 6); }},
       {"tall_dry_grass", [=](int x, int y) { return blades(x, y, 1533, dry, 12); }},
       {"firefly_bush",
        [=](int x, int y) {
          Texel t = blades(x, y, 1534, rgb(60, 100, 40), 12);
          if (t.alpha > 0.0f && hash01(1535, x, y) < 0.05f) t.color = rgb(240, 250, 120), t.emission = 250;
          return t;
        }},
       {"cactus_flower", [](int x, int y) { return plant(x, y, 1536, rgb(240, 110, 170)); }},
       {"spore_blossom", [](int x, int y) { return patches(x, y, 1537, rgb(220, 90, 170), 3.5f, 5); }},
       {"cobweb",
        [](int x, int y) {
          const bool thread = x == y || x == 15 - y || x == 7 || y == 7 ||
                              (std::abs(std::hypot(x - 7.5f, y - 7.5f) - 5.0f) < 0.6f);
          Texel t = clear();
          if (thread) t.color = rgb(235, 235, 235), t.alpha = 1.0f;
          return t;
        }},
       {"hanging_roots",
        [](int x, int y) { return strands(x, y, 1538, rgb(160, 110, 80), false, {}, false); }},
       {"mangrove_propagule", [](int x, int y) { return plant(x, y, 1539, rgb(120, 170, 60)); }},
       {"kelp", [](int x, int y) { return strands(x, y, 1540, rgb(80, 140, 40), true, {}, false); }},
       {"kelp_plant", [](int x, int y) { return blades(x, y, 1541, rgb(80, 140, 40), 14); }},
       {"sugar_cane",
        [=](int x, int y) {
          return x % 5 == 2 || x % 5 == 3 ? leafy(grey * (y % 5 == 0 ? 0.8f : 1.1f), 1542, x, y) : clear();
        }},
       {"cave_vines",
        [](int x, int y) { return strands(x, y, 1543, rgb(80, 110, 40), false, rgb(250, 170, 50), false); }},
       {"cave_vines_lit",
        [](int x, int y) { return strands(x, y, 1543, rgb(80, 110, 40), false, rgb(250, 170, 50), true); }},
       {"cave_vines_plant",
        [](int x, int y) { return strands(x, y, 1544, rgb(80, 110, 40), false, rgb(250, 170, 50), false); }},
       {"cave_vines_plant_lit",
        [](int x, int y) { return strands(x, y, 1544, rgb(80, 110, 40), false, rgb(250, 170, 50), true); }},
       {"weeping_vines",
        [](int x, int y) { return strands(x, y, 1545, rgb(160, 20, 30), false, {}, false); }},
       {"weeping_vines_plant",
        [](int x, int y) { return strands(x, y, 1546, rgb(160, 20, 30), false, {}, false); }},
       {"twisting_vines",
        [](int x, int y) { return strands(x, y, 1547, rgb(20, 150, 140), true, {}, false); }},
       {"twisting_vines_plant",
        [](int x, int y) { return strands(x, y, 1548, rgb(20, 150, 140), true, {}, false); }},
       {"pale_hanging_moss",
        [](int x, int y) { return strands(x, y, 1549, rgb(150, 155, 145), false, {}, false); }},
       {"pale_hanging_moss_tip",
        [](int x, int y) {
          return y < 10 ? strands(x, y, 1550, rgb(150, 155, 145), false, {}, false) : clear();
        }},
       {"vine", [=](int x, int y) { return patches(x, y, 1551, grey, 3.0f, 9); }},
       {"glow_lichen",
        [](int x, int y) {
          Texel t = patches(x, y, 1552, rgb(110, 140, 120), 2.6f, 7);
          if (t.alpha > 0.0f && hash01(1553, x, y) < 0.2f) t.color = rgb(200, 240, 200), t.emission = 200;
          return t;
        }},
       {"sculk_vein", [](int x, int y) { return patches(x, y, 1554, rgb(20, 60, 70), 2.4f, 8); }},
       {"resin_clump", [](int x, int y) { return patches(x, y, 1555, rgb(220, 110, 30), 2.6f, 6); }},
       {"pink_petals", [](int x, int y) { return patches(x, y, 1556, rgb(240, 170, 200), 2.4f, 7); }},
       {"wildflowers", [](int x, int y) { return patches(x, y, 1557, rgb(240, 230, 120), 2.2f, 7); }},
       {"leaf_litter", [](int x, int y) { return patches(x, y, 1558, rgb(150, 100, 50), 3.0f, 7); }},
       {"frogspawn", [](int x, int y) { return patches(x, y, 1559, rgb(60, 50, 50), 1.2f, 12); }},
       {"lily_pad",
        [=](int x, int y) {
          const float dx = x - 7.5f, dy = y - 7.5f;
          if (dx * dx + dy * dy > 52.0f || (dx > 0 && std::abs(dy) < 1.0f)) return clear();
          return leafy(rgb(40, 110, 40), 1560, x, y);
        }},
       {"fire_0", [](int x, int y) { return flame(x, y, 1561, rgb(255, 230, 120), rgb(250, 130, 30)); }},
       {"fire_1", [](int x, int y) { return flame(x, y, 1565, rgb(255, 230, 120), rgb(250, 130, 30)); }},
       {"soul_fire_0", [](int x, int y) { return flame(x, y, 1562, rgb(200, 250, 255), rgb(60, 200, 230)); }},
       {"soul_fire_1", [](int x, int y) { return flame(x, y, 1566, rgb(200, 250, 255), rgb(60, 200, 230)); }},
       {"campfire_fire",
        [](int x, int y) { return flame(x, y, 1563, rgb(255, 230, 120), rgb(250, 130, 30)); }},
       {"soul_campfire_fire",
        [](int x, int y) { return flame(x, y, 1564, rgb(200, 250, 255), rgb(60, 200, 230)); }}});
  // Double plants: leafy stalks below, the flower or the blades' tops above.
  const std::array<std::pair<const char*, glm::vec3>, 5> flowers = {{{"sunflower", rgb(250, 200, 30)},
                                                                     {"lilac", rgb(200, 150, 220)},
                                                                     {"rose_bush", rgb(200, 30, 40)},
                                                                     {"peony", rgb(240, 180, 220)},
                                                                     {"pitcher_plant", rgb(90, 150, 210)}}};
  std::uint64_t seed = 1570;
  for (const auto& [name, flower] : flowers) {
    const glm::vec3 f = flower;
    const std::uint64_t sd = seed++;
    out.push_back(
        still(std::string(name) + "_bottom", [=](int x, int y) { return blades(x, y, sd, green, 16); }));
    out.push_back(still(std::string(name) + "_top", [=](int x, int y) { return plant(x, y, sd, f); }));
  }
  for (const char* grass : {"tall_grass", "large_fern"}) {
    const std::uint64_t sd = seed++;
    out.push_back(
        still(std::string(grass) + "_bottom", [=](int x, int y) { return blades(x, y, sd, grey, 16); }));
    out.push_back(
        still(std::string(grass) + "_top", [=](int x, int y) { return blades(x, y, sd + 7, grey, 12); }));
  }
  out.push_back(
      still("tall_seagrass_bottom", [](int x, int y) { return blades(x, y, 1580, rgb(50, 130, 45), 16); }));
  out.push_back(
      still("tall_seagrass_top", [](int x, int y) { return blades(x, y, 1581, rgb(50, 130, 45), 12); }));
}

void addCaveAndSeaTextures(std::vector<GeneratedTexture>& out) {
  const std::array<std::pair<const char*, glm::vec3>, 5> corals = {{{"tube", rgb(50, 90, 210)},
                                                                    {"brain", rgb(210, 90, 160)},
                                                                    {"bubble", rgb(160, 30, 170)},
                                                                    {"fire", rgb(200, 40, 50)},
                                                                    {"horn", rgb(220, 200, 60)}}};
  std::uint64_t seed = 1600;
  for (const auto& [kind, colour] : corals) {
    for (const bool dead : {false, true}) {
      const glm::vec3 c = dead ? glm::vec3(0.5f, 0.48f, 0.46f) : colour;
      const std::string name = std::string(dead ? "dead_" : "") + kind + "_coral";
      const std::uint64_t sd = seed++;
      out.push_back(still(name, [=](int x, int y) { return coralPlant(x, y, sd, c, false); }));
      out.push_back(still(name + "_fan", [=](int x, int y) { return coralPlant(x, y, sd + 50, c, true); }));
    }
  }
  // Dripstone's five thicknesses pointing up (a stalagmite) or down (a stalactite).
  const std::array<std::tuple<const char*, float, float>, 5> thick = {{{"tip_merge", 1.0f, 1.0f},
                                                                       {"tip", 0.5f, 4.0f},
                                                                       {"frustum", 3.0f, 7.0f},
                                                                       {"middle", 6.0f, 8.0f},
                                                                       {"base", 8.0f, 12.0f}}};
  for (const auto& [name, narrow, wide] : thick) {
    const float n = narrow, w = wide;
    out.push_back(
        still(std::string("pointed_dripstone_up_") + name, [=](int x, int y) { return spike(x, y, n, w); }));
    out.push_back(still(std::string("pointed_dripstone_down_") + name,
                        [=](int x, int y) { return spike(x, y, w, n); }));
  }
  addAll(
      out,
      {{"amethyst_cluster", [](int x, int y) { return crystal(x, y, 14); }},
       {"large_amethyst_bud", [](int x, int y) { return crystal(x, y, 11); }},
       {"medium_amethyst_bud", [](int x, int y) { return crystal(x, y, 8); }},
       {"small_amethyst_bud", [](int x, int y) { return crystal(x, y, 5); }},
       {"big_dripleaf_top",
        [](int x, int y) {
          const float dx = x - 7.5f, dy = y - 7.5f;
          return dx * dx + dy * dy < 60.0f ? leafy(rgb(90, 150, 40), 1620, x, y) : clear();
        }},
       {"big_dripleaf_stem",
        [](int x, int y) { return x == 7 || x == 8 ? leafy(rgb(80, 130, 40), 1621, x, y) : clear(); }},
       {"sea_pickle",
        [](int x, int y) {
          Texel t = leafy(rgb(100, 120, 40), 1622, x, y);
          if (y < 3) t.color = rgb(200, 240, 160), t.emission = 200;
          return t;
        }},
       {"turtle_egg",
        [](int x, int y) {
          Texel t = smooth(x, y, 1623, rgb(230, 225, 200), 0.05f, 120);
          if (hash01(1624, x, y) < 0.15f) t.color = rgb(90, 150, 90);
          return t;
        }},
       {"sniffer_egg",
        [](int x, int y) {
          Texel t = smooth(x, y, 1625, rgb(170, 60, 50), 0.1f, 120);
          if ((x + y) % 7 == 0) t.color = rgb(60, 140, 110);
          return t;
        }},
       {"dried_ghast", [](int x, int y) { return rock(1626, x, y, rgb(190, 175, 160), 0.15f); }},
       {"cocoa_stage0", [](int x, int y) { return leafy(rgb(140, 160, 60), 1627, x, y); }},
       {"cocoa_stage1", [](int x, int y) { return leafy(rgb(170, 120, 50), 1628, x, y); }},
       {"cocoa_stage2", [](int x, int y) { return leafy(rgb(140, 80, 40), 1629, x, y); }},
       {"chorus_plant", [](int x, int y) { return rock(1630, x, y, rgb(95, 60, 95), 0.25f); }},
       {"chorus_flower",
        [](int x, int y) {
          return edged(rock(1631, x, y, rgb(160, 120, 160), 0.2f), x, y, rgb(110, 80, 110));
        }},
       {"chorus_flower_dead",
        [](int x, int y) { return edged(rock(1632, x, y, rgb(100, 80, 90), 0.2f), x, y, rgb(70, 55, 65)); }},
       {"bamboo_stalk",
        [](int x, int y) {
          Texel t = leafy(rgb(110, 160, 50), 1633, x, y);
          if (y % 8 == 0) t.color *= 0.7f;
          return t;
        }},
       {"bamboo_small_leaves", [](int x, int y) { return patches(x, y, 1634, rgb(80, 140, 40), 2.2f, 6); }},
       {"bamboo_large_leaves", [](int x, int y) { return patches(x, y, 1635, rgb(80, 140, 40), 3.2f, 7); }},
       {"bamboo_stage0", [](int x, int y) { return blades(x, y, 1636, rgb(110, 160, 50), 6); }},
       {"azalea_plant", [](int x, int y) { return blades(x, y, 1637, rgb(100, 80, 50), 8); }},
       {"flowering_azalea_plant", [](int x, int y) { return blades(x, y, 1638, rgb(100, 80, 50), 8); }}});
  for (const bool flowering : {false, true}) {
    const std::string kind = flowering ? "flowering_azalea" : "azalea";
    const auto leaves = [=](int x, int y) {
      Texel t = leafy(rgb(90, 130, 40), 1640, x, y);
      if (flowering && hash01(1641, x / 2, y / 2) < 0.25f) t.color = rgb(220, 120, 200);
      return t;
    };
    addAll(out, {{kind + "_top", leaves},
                 {kind + "_side", [=](int x, int y) { return y < 12 ? leaves(x, y) : clear(); }},
                 {kind + "_leaves",
                  [=](int x, int y) { return hash01(1642, x, y) < 0.2f ? clear() : leaves(x, y); }}});
  }
}

}  // namespace

void addGrowthTextures(std::vector<GeneratedTexture>& out) {
  addCropTextures(out);
  addPlantTexturesMore(out);
  addCaveAndSeaTextures(out);
}

}  // namespace terrasol::packgen
