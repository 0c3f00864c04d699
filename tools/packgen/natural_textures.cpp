// Textures of the natural blocks with faces of their own: soils with their own tops, nylium,
// roots, froglights, sculk, mushroom blocks, ancient debris, blackstone, chiseled stones, honey and
// slime, suspicious sand and gravel, frosted ice, the nether portal.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "texture_parts.h"

namespace terrasol::packgen {
namespace {

Texel topped(int x, int y, const Texel& top, const Texel& below, int depth) {
  const int edge = depth + static_cast<int>(2.0f * hash01(1503, x, 0));
  return y < edge ? top : below;
}

Texel mushroomCap(int x, int y, glm::vec3 cap, bool spots) {
  Texel t = rock(1504, x, y, cap, 0.12f);
  if (spots && voronoi(1505, x, y, 5).d1 < 1.8f) t.color = rgb(235, 230, 220);
  t.porosity = 80;
  return t;
}

// A glowing block of soft light across its face, its sides ribbed: froglights.
Texel froglight(int x, int y, glm::vec3 colour, bool top) {
  Texel t = smooth(x, y, 1506, colour, 0.08f, 140);
  t.emission = 240;
  if (!top && x % 5 == 0) t.color *= 0.85f;
  if (top && (x == 0 || y == 0 || x == 15 || y == 15)) t.color *= 0.8f;
  return t;
}

Texel sculkTex(int x, int y, std::uint64_t seed) {
  Texel t = rock(seed, x, y, rgb(15, 35, 45), 0.3f);
  if (hash01(seed + 1, x, y) < 0.07f) t.color = rgb(40, 200, 220), t.emission = 180;
  return t;
}

Texel chiseledStone(int x, int y, glm::vec3 colour) {
  Texel t = rock(1690, x, y, colour, 0.1f);
  const float r = std::hypot(x - 7.5f, y - 7.5f);
  if (rim(x, y) || std::abs(r - 4.5f) < 0.7f) t.color *= 0.65f, t.height = 0.5f;
  return t;
}

Texel honey(int x, int y, bool top) {
  Texel t = smooth(x, y, 1691, rgb(240, 170, 40), 0.1f, 230);
  t.alpha = top || rim(x, y) ? 0.9f : 0.7f;
  return t;
}

}  // namespace

void addNaturalTextures(std::vector<GeneratedTexture>& out) {
  const auto podzolTop = [](int x, int y) {
    Texel t = rock(1650, x, y, rgb(110, 75, 40), 0.25f);
    if (hash01(1651, x, y) < 0.15f) t.color = rgb(150, 110, 60);
    return t;
  };
  const auto myceliumTop = [](int x, int y) { return rock(1652, x, y, rgb(115, 95, 110), 0.2f); };
  const auto nylium = [](glm::vec3 c) { return [c](int x, int y) { return rock(1653, x, y, c, 0.2f); }; };
  addAll(
      out,
      {{"podzol_top", podzolTop},
       {"podzol_side", [=](int x, int y) { return topped(x, y, podzolTop(x, y), dirt(x, y), 3); }},
       {"mycelium_top", myceliumTop},
       {"mycelium_side", [=](int x, int y) { return topped(x, y, myceliumTop(x, y), dirt(x, y), 3); }},
       {"crimson_nylium", nylium(rgb(140, 25, 30))},
       {"crimson_nylium_side",
        [=](int x, int y) { return topped(x, y, nylium(rgb(140, 25, 30))(x, y), netherrack(x, y), 4); }},
       {"warped_nylium", nylium(rgb(30, 120, 110))},
       {"warped_nylium_side",
        [=](int x, int y) { return topped(x, y, nylium(rgb(30, 120, 110))(x, y), netherrack(x, y), 4); }},
       {"mangrove_roots_top",
        [](int x, int y) {
          return (x + y) % 5 == 0 || x % 6 == 1 ? logSideOf(x, y, rgb(90, 60, 40)) : clear();
        }},
       {"mangrove_roots_side",
        [](int x, int y) {
          return (x - y + 16) % 6 == 0 || x % 6 == 1 ? logSideOf(x, y, rgb(90, 60, 40)) : clear();
        }},
       {"muddy_mangrove_roots_top",
        [](int x, int y) {
          return x % 6 == 1 ? logSideOf(x, y, rgb(90, 60, 40)) : rock(1654, x, y, rgb(60, 55, 60), 0.2f);
        }},
       {"muddy_mangrove_roots_side",
        [](int x, int y) {
          return (x + y) % 6 == 0 ? logSideOf(x, y, rgb(90, 60, 40))
                                  : rock(1655, x, y, rgb(60, 55, 60), 0.2f);
        }},
       {"dried_kelp_top", [](int x, int y) { return rock(1656, x, y, rgb(50, 60, 35), 0.2f); }},
       {"dried_kelp_side",
        [](int x, int y) { return edged(rock(1657, x, y, rgb(55, 65, 35), 0.2f), x, y, rgb(35, 40, 25)); }},
       {"dried_kelp_bottom", [](int x, int y) { return rock(1658, x, y, rgb(45, 55, 30), 0.2f); }},
       {"honey_block_top", [](int x, int y) { return honey(x, y, true); }},
       {"honey_block_side", [](int x, int y) { return honey(x, y, false); }},
       {"honey_block_bottom", [](int x, int y) { return honey(x, y, false); }},
       {"slime_block",
        [](int x, int y) {
          Texel t = smooth(x, y, 1659, rgb(110, 190, 90), 0.1f, 220);
          t.alpha = rim(x, y) || (x >= 4 && x <= 11 && y >= 4 && y <= 11) ? 1.0f : 0.6f;
          return t;
        }},
       {"ochre_froglight_top", [](int x, int y) { return froglight(x, y, rgb(250, 230, 160), true); }},
       {"ochre_froglight_side", [](int x, int y) { return froglight(x, y, rgb(245, 220, 150), false); }},
       {"verdant_froglight_top", [](int x, int y) { return froglight(x, y, rgb(220, 245, 200), true); }},
       {"verdant_froglight_side", [](int x, int y) { return froglight(x, y, rgb(205, 235, 185), false); }},
       {"pearlescent_froglight_top", [](int x, int y) { return froglight(x, y, rgb(245, 225, 240), true); }},
       {"pearlescent_froglight_side",
        [](int x, int y) { return froglight(x, y, rgb(235, 210, 230), false); }},
       {"creaking_heart_top", [](int x, int y) { return logTopOf(x, y, rgb(80, 70, 65), rgb(120, 80, 60)); }},
       {"creaking_heart_side",
        [](int x, int y) {
          Texel t = logSideOf(x, y, rgb(80, 70, 65));
          if (x >= 6 && x <= 9 && y >= 6 && y <= 9) t.color = rgb(240, 120, 40), t.emission = 200;
          return t;
        }},
       {"sculk_catalyst_top",
        [](int x, int y) { return edged(sculkTex(x, y, 1660), x, y, rgb(220, 220, 200)); }},
       {"sculk_catalyst_side",
        [](int x, int y) {
          return y < 6 ? sculkTex(x, y, 1661) : rock(1662, x, y, rgb(220, 220, 200), 0.1f);
        }},
       {"sculk_catalyst_bottom", [](int x, int y) { return rock(1663, x, y, rgb(220, 220, 200), 0.1f); }},
       {"sculk_shrieker_top",
        [](int x, int y) { return edged(sculkTex(x, y, 1664), x, y, rgb(200, 200, 180)); }},
       {"sculk_shrieker_side",
        [](int x, int y) {
          return y > 8 ? sculkTex(x, y, 1665) : rock(1666, x, y, rgb(200, 200, 180), 0.1f);
        }},
       {"sculk_sensor_top", [](int x, int y) { return sculkTex(x, y, 1667); }},
       {"calibrated_sculk_sensor_top",
        [](int x, int y) {
          Texel t = sculkTex(x, y, 1668);
          if (x >= 6 && x <= 9 && y >= 6 && y <= 9) t.color = rgb(170, 110, 220), t.emission = 120;
          return t;
        }},
       {"sculk_sensor_tendril",
        [](int x, int y) { return x == 7 || x == 8 ? sculkTex(x, y, 1669) : clear(); }},
       {"nether_portal",
        [](int x, int y) {
          Texel t = smooth(x, y, 1670, rgb(110, 30, 200), 0.3f, 230);
          t.alpha = 0.75f;
          t.emission = 220;
          return t;
        }},
       {"mushroom_stem", [](int x, int y) { return rock(1671, x, y, rgb(205, 200, 185), 0.08f); }},
       {"mushroom_block_inside", [](int x, int y) { return rock(1672, x, y, rgb(210, 180, 140), 0.12f); }},
       {"brown_mushroom_block", [](int x, int y) { return mushroomCap(x, y, rgb(150, 110, 80), false); }},
       {"red_mushroom_block", [](int x, int y) { return mushroomCap(x, y, rgb(190, 40, 40), true); }},
       {"ancient_debris_side",
        [](int x, int y) {
          Texel t = rock(1673, x, y, rgb(95, 65, 55), 0.25f);
          if (y % 5 == 0) t.color *= 0.7f;
          return t;
        }},
       {"ancient_debris_top",
        [](int x, int y) { return edged(rock(1674, x, y, rgb(95, 65, 55), 0.25f), x, y, rgb(70, 50, 45)); }},
       {"blackstone", [](int x, int y) { return rock(1675, x, y, rgb(45, 40, 48), 0.25f); }},
       {"blackstone_top",
        [](int x, int y) { return edged(rock(1676, x, y, rgb(45, 40, 48), 0.2f), x, y, rgb(35, 30, 38)); }},
       {"gilded_blackstone",
        [](int x, int y) {
          Texel t = rock(1677, x, y, rgb(45, 40, 48), 0.25f);
          if (voronoi(1678, x, y, 4).d1 < 1.7f) t.color = rgb(230, 180, 60), t.f0 = 231, t.smoothness = 200;
          return t;
        }},
       {"chiseled_polished_blackstone", [](int x, int y) { return chiseledStone(x, y, rgb(55, 48, 58)); }},
       {"chiseled_nether_bricks", [](int x, int y) { return chiseledStone(x, y, rgb(60, 30, 35)); }},
       {"chiseled_stone_bricks", [](int x, int y) { return chiseledStone(x, y, rgb(120, 120, 120)); }},
       {"chiseled_resin_bricks", [](int x, int y) { return chiseledStone(x, y, rgb(210, 100, 30)); }},
       {"chiseled_deepslate", [](int x, int y) { return chiseledStone(x, y, rgb(60, 60, 66)); }},
       {"chiseled_tuff", [](int x, int y) { return chiseledStone(x, y, rgb(110, 112, 100)); }},
       {"chiseled_tuff_top",
        [](int x, int y) {
          return edged(rock(1679, x, y, rgb(110, 112, 100), 0.1f), x, y, rgb(80, 82, 75));
        }},
       {"chiseled_tuff_bricks", [](int x, int y) { return chiseledStone(x, y, rgb(100, 104, 95)); }},
       {"chiseled_tuff_bricks_top",
        [](int x, int y) { return edged(rock(1680, x, y, rgb(100, 104, 95), 0.1f), x, y, rgb(75, 78, 70)); }},
       {"bamboo_mosaic",
        [](int x, int y) { return planksOf((x / 8) % 2 ? y : x, (x / 8) % 2 ? x : y, rgb(200, 180, 80)); }},
       {"reinforced_deepslate_top",
        [](int x, int y) {
          return edged(rock(1681, x, y, rgb(60, 62, 66), 0.2f), x, y, rgb(150, 150, 140));
        }},
       {"reinforced_deepslate_side",
        [](int x, int y) {
          return edged(rock(1682, x, y, rgb(55, 58, 62), 0.2f), x, y, rgb(150, 150, 140));
        }},
       {"reinforced_deepslate_bottom",
        [](int x, int y) { return rock(1683, x, y, rgb(55, 58, 62), 0.2f); }}});
  for (int d = 0; d <= 3; ++d) {
    out.push_back(still("suspicious_sand_" + std::to_string(d), [=](int x, int y) {
      Texel t = rock(101, x, y, rgb(219, 207, 163), 0.08f);
      if (voronoi(1684, x, y, 3).d1 < 1.5f + d * 0.5f) t.color *= 0.8f;
      return t;
    }));
    out.push_back(still("suspicious_gravel_" + std::to_string(d), [=](int x, int y) {
      Texel t = cobblestone(x, y);
      t.color = t.color * rgb(255, 245, 235) * 1.05f;
      if (voronoi(1685, x, y, 3).d1 < 1.5f + d * 0.5f) t.color *= 0.75f;
      return t;
    }));
  }
  for (int age = 0; age <= 3; ++age) {
    out.push_back(still("frosted_ice_" + std::to_string(age), [=](int x, int y) {
      Texel t = smooth(x, y, 1686, rgb(160, 190, 240), 0.08f, 240);
      t.alpha = 0.75f;
      if (hash01(1687, x, y) < 0.08f * age) t.color = rgb(230, 240, 255), t.alpha = 0.95f;
      return t;
    }));
  }
}

}  // namespace terrasol::packgen
