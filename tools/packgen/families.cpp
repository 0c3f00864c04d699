// The block families beyond the first blocks: more stones, the other woods, sandstone, coloured wool,
// concrete, terracotta and stained glass, crafted blocks, plants, more ores and the metal and gem blocks.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "recipes.h"

namespace terrasol::packgen {
namespace {

Texel deepslate(int x, int y) {
  Texel t = rock(301, x, y / 2, rgb(80, 80, 86), 0.2f);  // stretched: its layers run across
  t.height = 0.5f + 0.5f * t.height;
  return t;
}
Texel cobbledDeepslate(int x, int y) {
  Texel t = cobblestone(x, y);
  t.color *= rgb(80, 80, 90) / rgb(120, 120, 120);
  return t;
}

Texel sandstoneSide(int x, int y, glm::vec3 colour) {
  Texel t = rock(311, x, y, colour, 0.06f);
  const int band = y % 5;
  t.color *= band == 0 ? 0.88f : 1.0f;
  t.height = band == 0 ? 0.7f : 0.95f;
  t.porosity = 40;
  return t;
}

Texel wool(int x, int y, glm::vec3 colour) {
  const float fibre = tileNoise(201, x * 1.0f, y * 2.0f, 8) * 0.6f +
                      fbm(202, static_cast<float>(x), static_cast<float>(y)) * 0.4f;
  Texel t;
  t.color = colour * (0.86f + 0.16f * fibre);
  t.height = 0.5f + 0.5f * fibre;
  t.smoothness = 15;
  t.porosity = 120;
  return t;
}
Texel concrete(int x, int y, glm::vec3 colour) {
  return smooth(x, y, 411, colour, 0.03f, 120);
}
Texel stainedGlass(int x, int y, glm::vec3 colour) {
  Texel t = glass(x, y);
  t.color = colour * (t.alpha > 0.5f ? 0.8f : 1.0f);
  t.alpha = t.alpha > 0.5f ? 1.0f : 0.55f;  // translucent, its frame opaque
  return t;
}

// A wood's planks, logs (bark and rings), stripped logs, leaves, door and trapdoor.
struct Wood {
  const char* name;
  glm::vec3 planks, bark, core;
  std::uint64_t leafSeed;
  glm::vec3 leaves{-1.0f};  // the leaves' own colour; negative: grey, for the biome's foliage tint
};

void addWood(std::vector<GeneratedTexture>& out, const Wood& w) {
  const std::string n = w.name;
  out.push_back(still(n + "_planks", [w](int x, int y) { return planksOf(x, y, w.planks); }));
  out.push_back(still(n + "_log", [w](int x, int y) { return logSideOf(x, y, w.bark); }));
  out.push_back(still(n + "_log_top", [w](int x, int y) { return logTopOf(x, y, w.bark, w.core); }));
  out.push_back(
      still("stripped_" + n + "_log", [w](int x, int y) { return logSideOf(x, y, w.core * 0.85f); }));
  out.push_back(still("stripped_" + n + "_log_top",
                      [w](int x, int y) { return logTopOf(x, y, w.core * 0.85f, w.core); }));
  out.push_back(still(n + "_leaves", [w](int x, int y) {
    Texel t = leavesOf(x, y, w.leafSeed);
    if (w.leaves.r >= 0.0f) t.color *= w.leaves / glm::vec3(0.6f);
    return t;
  }));
  out.push_back(still(n + "_door_bottom", [w](int x, int y) { return doorBottom(x, y, w.planks); }));
  out.push_back(still(n + "_door_top", [w](int x, int y) { return doorTop(x, y, w.planks); }));
  out.push_back(still(n + "_trapdoor", [w](int x, int y) { return trapdoor(x, y, w.planks); }));
}

Texel bookshelf(int x, int y) {
  if (y <= 1 || y >= 14 || y == 7 || y == 8) return planks(x, y);
  const int book = x / 2;
  Texel t;
  t.color = dye(static_cast<std::size_t>((book * 5 + (y > 8 ? 3 : 0)) % 16)) * 0.8f + glm::vec3(0.1f);
  t.height = x % 2 ? 0.85f : 1.0f;
  t.smoothness = 50;
  return t;
}

Texel pumpkinSide(int x, int y) {
  Texel t = rock(501, x, y, rgb(206, 118, 21), 0.06f);
  if (x % 4 == 0) t.color *= 0.75f, t.height = 0.6f;  // the ribs
  t.smoothness = 90;
  return t;
}

Texel melonSide(int x, int y) {
  Texel t = rock(511, x, y, (x / 2) % 2 ? rgb(114, 146, 30) : rgb(145, 170, 45), 0.05f);
  t.smoothness = 100;
  return t;
}

Texel cactusSide(int x, int y) {
  if (x == 0 || x == 15) {
    Texel t;
    t.alpha = 0.0f;
    return t;
  }
  Texel t = rock(521, x, y, rgb(80, 130, 40), 0.1f);
  if ((x == 3 || x == 12) && y % 4 == 1) t.color = rgb(220, 220, 170), t.height = 1.0f;  // spines
  t.porosity = 80;
  return t;
}

}  // namespace

// Laid out as Minecraft's lantern.png, where its model's faces read: the cage's sides (x 0..5,
// y 2..8: a metal frame round the glow), the cage's top and bottom (y 9..14) and the cap's sides
// (x 1..4, y 0..1) in metal; the rest is empty.
Texel lantern(int x, int y) {
  Texel t;
  t.alpha = 0.0f;
  const bool capSide = y <= 1 && x >= 1 && x <= 4;
  const bool cageSide = y >= 2 && y <= 8 && x <= 5;
  const bool cageEnd = y >= 9 && y <= 14 && x <= 5;
  if (capSide || cageEnd || (cageSide && (x == 0 || x == 5 || y == 2 || y == 8))) {
    t = metalBlock(x, y, rgb(70, 75, 85), 230, 150);
  } else if (cageSide) {
    t.color = rgb(255, 210, 120);
    t.alpha = 1.0f;
    t.emission = 220;
    t.smoothness = 200;
  }
  return t;
}

void addFamilyTextures(std::vector<GeneratedTexture>& out) {
  // Stones.
  out.push_back(still("mossy_cobblestone", [](int x, int y) { return moss(cobblestone(x, y), x, y, 601); }));
  out.push_back(still("smooth_stone", [](int x, int y) { return polished(stone(x, y), x, y); }));
  // A slab's side: two polished halves with the seam between them.
  out.push_back(still("smooth_stone_slab_side",
                      [](int x, int y) { return polished(stone(x, y), x, y % 8 == 7 ? kSize - 1 : y % 8); }));
  out.push_back(still("stone_bricks", [](int x, int y) {
    return bricks(x, y, 611, rgb(122, 122, 122), rgb(90, 90, 90), 4, 8);
  }));
  out.push_back(still("cracked_stone_bricks", [](int x, int y) {
    return crack(bricks(x, y, 611, rgb(122, 122, 122), rgb(90, 90, 90), 4, 8), x, y);
  }));
  out.push_back(still("mossy_stone_bricks", [](int x, int y) {
    return moss(bricks(x, y, 611, rgb(122, 122, 122), rgb(90, 90, 90), 4, 8), x, y, 612);
  }));
  const auto granite = [](int x, int y) {
    return speckled(x, y, 621, rgb(149, 103, 85), rgb(190, 150, 135), 0.25f);
  };
  const auto diorite = [](int x, int y) {
    return speckled(x, y, 631, rgb(188, 188, 188), rgb(110, 110, 110), 0.2f);
  };
  const auto andesite = [](int x, int y) {
    return speckled(x, y, 641, rgb(136, 136, 137), rgb(160, 160, 160), 0.15f);
  };
  out.push_back(still("granite", granite));
  out.push_back(still("polished_granite", [granite](int x, int y) { return polished(granite(x, y), x, y); }));
  out.push_back(still("diorite", diorite));
  out.push_back(still("polished_diorite", [diorite](int x, int y) { return polished(diorite(x, y), x, y); }));
  out.push_back(still("andesite", andesite));
  out.push_back(
      still("polished_andesite", [andesite](int x, int y) { return polished(andesite(x, y), x, y); }));
  out.push_back(still("deepslate", deepslate));
  out.push_back(still("deepslate_top", [](int x, int y) { return rock(302, x, y, rgb(84, 84, 90), 0.2f); }));
  out.push_back(still("cobbled_deepslate", cobbledDeepslate));
  out.push_back(still("polished_deepslate", [](int x, int y) { return polished(deepslate(x, y), x, y); }));
  out.push_back(still("tuff", [](int x, int y) {
    return speckled(x, y, 651, rgb(108, 109, 102), rgb(130, 125, 110), 0.2f);
  }));
  out.push_back(
      still("calcite", [](int x, int y) { return smooth(x, y, 661, rgb(223, 224, 220), 0.05f, 110); }));
  out.push_back(
      still("obsidian", [](int x, int y) { return smooth(x, y, 671, rgb(20, 18, 30), 0.4f, 220); }));
  out.push_back(still(
      "bricks", [](int x, int y) { return bricks(x, y, 681, rgb(150, 74, 58), rgb(170, 160, 150), 4, 8); }));
  // Sand and sandstone, clay, ice.
  out.push_back(still("red_sand", [](int x, int y) { return rock(691, x, y, rgb(190, 102, 33), 0.08f); }));
  const glm::vec3 sandstone = rgb(216, 203, 155);
  out.push_back(still("sandstone", [sandstone](int x, int y) { return sandstoneSide(x, y, sandstone); }));
  out.push_back(
      still("sandstone_top", [sandstone](int x, int y) { return smooth(x, y, 701, sandstone, 0.05f, 40); }));
  out.push_back(
      still("sandstone_bottom", [sandstone](int x, int y) { return rock(702, x, y, sandstone, 0.1f); }));
  out.push_back(still("cut_sandstone", [sandstone](int x, int y) {
    return polished(smooth(x, y, 703, sandstone, 0.05f, 40), x, y);
  }));
  // Red sandstone, as sandstone in the badlands' red sand; chiseled: a carved band across the middle.
  const glm::vec3 red = rgb(186, 99, 29);
  out.push_back(still("red_sandstone", [red](int x, int y) { return sandstoneSide(x, y, red); }));
  out.push_back(
      still("red_sandstone_top", [red](int x, int y) { return smooth(x, y, 704, red, 0.05f, 40); }));
  out.push_back(still("red_sandstone_bottom", [red](int x, int y) { return rock(705, x, y, red, 0.1f); }));
  out.push_back(still("cut_red_sandstone",
                      [red](int x, int y) { return polished(smooth(x, y, 706, red, 0.05f, 40), x, y); }));
  out.push_back(still("chiseled_red_sandstone", [red](int x, int y) {
    Texel t = sandstoneSide(x, y, red);
    if (y >= 5 && y <= 10 && (x + y) % 4 == 0) t.color *= 0.7f, t.height = 0.5f;
    return t;
  }));
  out.push_back(still("chiseled_sandstone", [sandstone](int x, int y) {
    Texel t = sandstoneSide(x, y, sandstone);
    if (y >= 5 && y <= 10 && (x + y) % 4 == 0) t.color *= 0.7f, t.height = 0.5f;
    return t;
  }));
  // Quartz: smooth white faces; the block's side and top framed, its bottom plain (smooth quartz).
  const glm::vec3 quartz = rgb(236, 230, 223);
  out.push_back(still("quartz_block_side", [quartz](int x, int y) {
    return polished(smooth(x, y, 707, quartz, 0.03f, 150), x, y);
  }));
  out.push_back(still("quartz_block_top", [quartz](int x, int y) {
    return polished(smooth(x, y, 708, quartz, 0.03f, 150), x, y);
  }));
  out.push_back(
      still("quartz_block_bottom", [quartz](int x, int y) { return smooth(x, y, 709, quartz, 0.03f, 150); }));
  out.push_back(still("chiseled_quartz_block", [quartz](int x, int y) {
    Texel t = polished(smooth(x, y, 710, quartz, 0.03f, 150), x, y);
    if ((x == 4 || x == 11) && y > 2 && y < 13) t.color *= 0.8f, t.height = 0.6f;
    return t;
  }));
  out.push_back(still("chiseled_quartz_block_top", [quartz](int x, int y) {
    Texel t = polished(smooth(x, y, 711, quartz, 0.03f, 150), x, y);
    const int r = std::max(std::abs(x - 7), std::abs(y - 7));
    if (r == 3) t.color *= 0.8f, t.height = 0.6f;
    return t;
  }));
  out.push_back(still("clay", [](int x, int y) { return smooth(x, y, 711, rgb(160, 166, 179), 0.05f, 70); }));
  out.push_back(still("packed_ice", [](int x, int y) {
    Texel t = smooth(x, y, 721, rgb(141, 180, 250), 0.1f, 230);
    t.f0 = 5;
    return t;
  }));
  out.push_back(still("terracotta", [](int x, int y) { return terracotta(x, y, rgb(152, 94, 67)); }));
  // The sixteen colours of wool, concrete, terracotta and stained glass.
  for (std::size_t i = 0; i < kDyes.size(); ++i) {
    const std::string c = kDyes[i].first;
    const glm::vec3 colour = dye(i);
    out.push_back(still(c + "_wool", [colour](int x, int y) { return wool(x, y, colour); }));
    out.push_back(still(c + "_concrete", [colour](int x, int y) { return concrete(x, y, colour); }));
    out.push_back(still(c + "_stained_glass", [colour](int x, int y) { return stainedGlass(x, y, colour); }));
  }
  // Woods.
  for (const Wood& w :
       {Wood{"birch", rgb(192, 175, 121), rgb(216, 215, 210), rgb(200, 180, 130), 731},
        Wood{"spruce", rgb(114, 84, 48), rgb(58, 37, 16), rgb(120, 90, 55), 741},
        Wood{"acacia", rgb(168, 90, 50), rgb(103, 96, 86), rgb(175, 95, 55), 751},
        Wood{"dark_oak", rgb(66, 43, 20), rgb(60, 46, 26), rgb(75, 50, 25), 761},
        Wood{"jungle", rgb(160, 115, 80), rgb(85, 67, 25), rgb(170, 120, 80), 771},
        Wood{"cherry", rgb(226, 178, 172), rgb(54, 33, 44), rgb(226, 160, 160), 781, rgb(235, 170, 200)},
        Wood{"mangrove", rgb(117, 54, 48), rgb(84, 66, 50), rgb(118, 54, 48), 791},
        Wood{"pale_oak", rgb(223, 212, 208), rgb(90, 85, 80), rgb(230, 220, 215), 801, rgb(160, 170, 160)}}) {
    addWood(out, w);
  }
  out.push_back(
      still("stripped_oak_log", [](int x, int y) { return logSideOf(x, y, rgb(176, 143, 88) * 0.85f); }));
  out.push_back(still("stripped_oak_log_top", [](int x, int y) {
    return logTopOf(x, y, rgb(176, 143, 88) * 0.85f, rgb(176, 143, 88));
  }));
  // Crafted blocks and plants.
  out.push_back(still("bookshelf", bookshelf));
  out.push_back(still("crafting_table_top", [](int x, int y) {
    Texel t = planks(x, y);
    if (x == 0 || y == 0 || x == 15 || y == 15 || x == 7 || y == 7) t.color *= 0.6f, t.height = 0.6f;
    return t;
  }));
  out.push_back(still("crafting_table_side", [](int x, int y) {
    Texel t = planks(x, y);
    if (y < 3) t.color *= 0.7f;
    if ((x == 4 || x == 11) && y > 4 && y < 12) t = metalBlock(x, y, rgb(140, 140, 140), 230, 120);  // tools
    return t;
  }));
  out.push_back(still("pumpkin_side", pumpkinSide));
  out.push_back(still("pumpkin_top", [](int x, int y) {
    Texel t = pumpkinSide(x, y);
    const float dx = x - 7.5f, dy = y - 7.5f;
    if (dx * dx + dy * dy < 3.0f) t.color = rgb(90, 120, 40);  // the stem
    return t;
  }));
  out.push_back(still("melon_side", melonSide));
  out.push_back(still("melon_top", [](int x, int y) { return rock(512, x, y, rgb(120, 150, 35), 0.1f); }));
  out.push_back(still("cactus_side", cactusSide));
  out.push_back(still("cactus_top", [](int x, int y) { return rock(522, x, y, rgb(90, 140, 50), 0.1f); }));
  out.push_back(still("dead_bush", [](int x, int y) {
    Texel t = plant(x, y, 531, glm::vec3(-1.0f));
    t.color = rgb(148, 100, 40) * (t.alpha > 0.5f ? 1.0f : 0.0f);
    return t;
  }));
  out.push_back(still("fern", [](int x, int y) { return plant(x, y, 541, glm::vec3(-1.0f)); }));
  out.push_back(still("blue_orchid", [](int x, int y) { return plant(x, y, 551, rgb(40, 170, 230)); }));
  out.push_back(still("allium", [](int x, int y) { return plant(x, y, 552, rgb(180, 100, 230)); }));
  out.push_back(still("azure_bluet", [](int x, int y) { return plant(x, y, 553, rgb(240, 240, 250)); }));
  out.push_back(still("oxeye_daisy", [](int x, int y) { return plant(x, y, 554, rgb(250, 250, 230)); }));
  out.push_back(still("cornflower", [](int x, int y) { return plant(x, y, 555, rgb(70, 100, 220)); }));
  out.push_back(still("lantern", lantern));
  // Ores, in stone and in deepslate, and the metal and gem blocks.
  out.push_back(still("nether_gold_ore",
                      [](int x, int y) { return oreIn(x, y, 191, rgb(250, 210, 60), 231, netherrack); }));
  out.push_back(still("nether_quartz_ore",
                      [](int x, int y) { return oreIn(x, y, 192, rgb(235, 230, 220), 40, netherrack); }));
  out.push_back(
      still("redstone_ore", [](int x, int y) { return oreIn(x, y, 193, rgb(210, 20, 10), 60, stone); }));
  out.push_back(still("deepslate_redstone_ore",
                      [](int x, int y) { return oreIn(x, y, 193, rgb(210, 20, 10), 60, deepslate); }));
  out.push_back(still("deepslate_emerald_ore",
                      [](int x, int y) { return oreIn(x, y, 194, rgb(50, 200, 100), 60, deepslate); }));
  out.push_back(still("deepslate_coal_ore",
                      [](int x, int y) { return oreIn(x, y, 181, rgb(45, 45, 45), 12, deepslate); }));
  out.push_back(still("deepslate_iron_ore",
                      [](int x, int y) { return oreIn(x, y, 182, rgb(216, 175, 147), 230, deepslate); }));
  out.push_back(still("deepslate_gold_ore",
                      [](int x, int y) { return oreIn(x, y, 183, rgb(250, 220, 80), 231, deepslate); }));
  out.push_back(
      still("copper_ore", [](int x, int y) { return oreIn(x, y, 184, rgb(200, 110, 75), 234, stone); }));
  out.push_back(still("deepslate_copper_ore",
                      [](int x, int y) { return oreIn(x, y, 184, rgb(200, 110, 75), 234, deepslate); }));
  // Gems are dielectrics: very smooth, with their own F0 (diamond n 2.42: 0.17; emerald n 1.58: 0.05).
  const auto gem = [](int x, int y, std::uint64_t seed, glm::vec3 colour, int f0, Texel (*ground)(int, int)) {
    Texel t = oreIn(x, y, seed, colour, f0, ground);
    if (t.height == 1.0f && t.porosity == 0) t.smoothness = 235;  // the gem's texels, not the rock's
    return t;
  };
  out.push_back(
      still("diamond_ore", [gem](int x, int y) { return gem(x, y, 185, rgb(90, 230, 220), 44, stone); }));
  out.push_back(still("deepslate_diamond_ore",
                      [gem](int x, int y) { return gem(x, y, 185, rgb(90, 230, 220), 44, deepslate); }));
  out.push_back(
      still("emerald_ore", [gem](int x, int y) { return gem(x, y, 186, rgb(40, 200, 90), 13, stone); }));
  out.push_back(
      still("lapis_ore", [gem](int x, int y) { return gem(x, y, 187, rgb(30, 60, 170), 10, stone); }));
  out.push_back(still("deepslate_lapis_ore",
                      [gem](int x, int y) { return gem(x, y, 187, rgb(30, 60, 170), 10, deepslate); }));
  const auto gemBlock = [](int x, int y, glm::vec3 colour, int f0) {
    Texel t = polished(smooth(x, y, 801, colour, 0.08f, 235), x, y);
    t.f0 = f0;
    return t;
  };
  out.push_back(
      still("diamond_block", [gemBlock](int x, int y) { return gemBlock(x, y, rgb(100, 230, 225), 44); }));
  out.push_back(
      still("emerald_block", [gemBlock](int x, int y) { return gemBlock(x, y, rgb(50, 200, 100), 13); }));
  out.push_back(still("lapis_block", [](int x, int y) { return rock(811, x, y, rgb(35, 65, 160), 0.15f); }));
  out.push_back(
      still("exposed_copper", [](int x, int y) { return metalBlock(x, y, rgb(160, 120, 95), 234, 150); }));
  out.push_back(still("weathered_copper", [](int x, int y) {
    Texel t = metalBlock(x, y, rgb(110, 150, 110), 234, 100);
    if (fbm(821, static_cast<float>(x), static_cast<float>(y)) > 0.5f)
      t.color = rgb(80, 160, 130), t.f0 = 20, t.smoothness = 50;
    return t;
  }));
  out.push_back(still("oxidized_copper", [](int x, int y) {
    Texel t = rock(831, x, y, rgb(82, 162, 132), 0.1f);  // verdigris: no longer a metal
    t.smoothness = 60;
    return t;
  }));
}

}  // namespace terrasol::packgen
