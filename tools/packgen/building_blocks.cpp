// Minecraft's plain building blocks beyond the first families: terracotta in sixteen colours,
// concrete powder, stained panes' edges, the newer woods' planks, bricks and tiles of deepslate, blackstone,
// the Nether, the End, mud, tuff, prismarine, purpur, quartz and resin, raw ore and mineral blocks, corals
// living and dead, the weathered coppers, and the soils. Each texture is named as its block, which draws it
// on every side.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "recipes.h"

namespace terrasol::packgen {
namespace {

// Minecraft's stained terracotta, muted and earthy beside its dyes.
constexpr std::array<std::array<int, 3>, 16> kTerracotta = {{{209, 178, 161},
                                                             {161, 83, 37},
                                                             {149, 88, 108},
                                                             {113, 108, 137},
                                                             {186, 133, 35},
                                                             {103, 117, 52},
                                                             {161, 78, 78},
                                                             {57, 42, 35},
                                                             {135, 106, 97},
                                                             {86, 91, 91},
                                                             {118, 70, 86},
                                                             {74, 59, 91},
                                                             {77, 51, 35},
                                                             {76, 83, 42},
                                                             {143, 61, 46},
                                                             {37, 22, 16}}};

glm::vec3 rgbOf(const std::array<int, 3>& c) {
  return rgb(c[0], c[1], c[2]);
}

// Concrete before water sets it: its colour, lighter, in loose grains.
Texel powder(int x, int y, glm::vec3 colour) {
  Texel t = rock(431, x, y, colour * 0.88f + glm::vec3(0.1f), 0.16f);
  t.height = 0.6f + 0.4f * t.height;
  t.smoothness = 20;
  t.porosity = 90;
  return t;
}

// Square tiles `size` texels across with dark joints.
Texel tiles(int x, int y, std::uint64_t seed, glm::vec3 tile, glm::vec3 joint, int size) {
  return bricks(x, y, seed, tile, joint, size, size);
}

// Cut metal: a block of four plates with sunken seams.
Texel cutMetal(int x, int y, glm::vec3 base, int f0, int smoothness) {
  Texel t = metalBlock(x, y, base, f0, smoothness);
  if (x % 8 == 0 || y % 8 == 0) t.color *= 0.75f, t.height = 0.6f;
  return t;
}

// Oxidized copper is no longer bare metal: a patina, rough, dielectric.
Texel patina(int x, int y, glm::vec3 colour, std::uint64_t seed) {
  Texel t = rock(seed, x, y, colour, 0.14f);
  t.smoothness = 70;
  t.porosity = 40;
  return t;
}

Texel coral(int x, int y, glm::vec3 colour, std::uint64_t seed) {
  Texel t = rock(seed, x, y, colour, 0.22f);
  const float pore = hash01(seed + 3, x / 2, y / 2);
  if (pore < 0.18f) t.color *= 0.6f, t.height = 0.3f;
  t.porosity = 150;
  t.smoothness = 30;
  return t;
}

// A stained pane's edge: its glass's colour, opaque, lighter along the middle.
Texel paneEdgeOf(int x, int y, glm::vec3 colour) {
  Texel t = glass(0, y);
  t.color = colour * (x == 7 || x == 8 ? 0.9f : 0.8f);
  t.alpha = 1.0f;
  return t;
}

void addDyedBlocks(std::vector<GeneratedTexture>& out) {
  for (std::size_t i = 0; i < kDyes.size(); ++i) {
    const std::string c = kDyes[i].first;
    const glm::vec3 fired = rgbOf(kTerracotta[i]), colour = dye(i);
    out.push_back(still(c + "_terracotta", [fired](int x, int y) { return terracotta(x, y, fired); }));
    out.push_back(still(c + "_concrete_powder", [colour](int x, int y) { return powder(x, y, colour); }));
    out.push_back(
        still(c + "_stained_glass_pane_top", [colour](int x, int y) { return paneEdgeOf(x, y, colour); }));
  }
}

void addPlanks(std::vector<GeneratedTexture>& out) {
  // The woods without logs here; the others' planks come with their logs (families.cpp).
  const std::array<std::pair<const char*, glm::vec3>, 3> woods = {
      {{"bamboo", rgb(193, 173, 80)}, {"crimson", rgb(101, 48, 70)}, {"warped", rgb(43, 104, 99)}}};
  for (const auto& [wood, colour] : woods) {
    const glm::vec3 c = colour;
    const std::string w = wood;
    out.push_back(still(w + "_planks", [c](int x, int y) { return planksOf(x, y, c); }));
    out.push_back(still(w + "_door_bottom", [c](int x, int y) { return doorBottom(x, y, c); }));
    out.push_back(still(w + "_door_top", [c](int x, int y) { return doorTop(x, y, c); }));
    out.push_back(still(w + "_trapdoor", [c](int x, int y) { return trapdoor(x, y, c); }));
  }
}

void addBricksAndTiles(std::vector<GeneratedTexture>& out) {
  const auto brick = [&](const char* name, glm::vec3 b, glm::vec3 m, std::uint64_t seed, bool cracked) {
    out.push_back(still(name, [=](int x, int y) {
      const Texel t = bricks(x, y, seed, b, m, 4, 8);
      return cracked ? crack(t, x, y) : t;
    }));
  };
  brick("deepslate_bricks", rgb(72, 72, 78), rgb(42, 42, 47), 801, false);
  brick("cracked_deepslate_bricks", rgb(72, 72, 78), rgb(42, 42, 47), 801, true);
  brick("polished_blackstone_bricks", rgb(52, 46, 56), rgb(28, 24, 30), 811, false);
  brick("cracked_polished_blackstone_bricks", rgb(52, 46, 56), rgb(28, 24, 30), 811, true);
  brick("nether_bricks", rgb(48, 24, 28), rgb(22, 11, 13), 821, false);
  brick("cracked_nether_bricks", rgb(48, 24, 28), rgb(22, 11, 13), 821, true);
  brick("red_nether_bricks", rgb(75, 10, 12), rgb(42, 5, 7), 831, false);
  brick("end_stone_bricks", rgb(220, 224, 163), rgb(186, 186, 130), 841, false);
  brick("mud_bricks", rgb(140, 106, 80), rgb(108, 82, 62), 851, false);
  brick("tuff_bricks", rgb(100, 104, 93), rgb(70, 72, 65), 861, false);
  brick("quartz_bricks", rgb(236, 231, 223), rgb(208, 202, 193), 871, false);
  brick("resin_bricks", rgb(208, 102, 30), rgb(158, 70, 20), 881, false);
  brick("prismarine_bricks", rgb(99, 171, 158), rgb(66, 128, 118), 891, false);
  const auto tile = [&](const char* name, glm::vec3 t, glm::vec3 j, std::uint64_t seed, int size,
                        bool cracked) {
    out.push_back(still(name, [=](int x, int y) {
      const Texel texel = tiles(x, y, seed, t, j, size);
      return cracked ? crack(texel, x, y) : texel;
    }));
  };
  tile("deepslate_tiles", rgb(60, 60, 66), rgb(34, 34, 38), 901, 4, false);
  tile("cracked_deepslate_tiles", rgb(60, 60, 66), rgb(34, 34, 38), 901, 4, true);
  tile("purpur_block", rgb(169, 125, 169), rgb(128, 90, 128), 911, 8, false);
  tile("dark_prismarine", rgb(52, 92, 76), rgb(30, 60, 50), 921, 8, false);
}

// A rock of one colour, as porous as `porosity` says.
void addRock(std::vector<GeneratedTexture>& out, const char* name, std::uint64_t seed, glm::vec3 colour,
             float contrast, int porosity) {
  out.push_back(still(name, [=](int x, int y) {
    Texel t = rock(seed, x, y, colour, contrast);
    t.porosity = porosity;
    return t;
  }));
}

void addStonesAndSoils(std::vector<GeneratedTexture>& out) {
  out.push_back(still("netherrack", netherrack));
  addRock(out, "end_stone", 942, rgb(219, 222, 158), 0.12f, 40);
  addRock(out, "soul_soil", 943, rgb(75, 57, 46), 0.22f, 120);
  addRock(out, "packed_mud", 944, rgb(142, 106, 79), 0.1f, 60);
  addRock(out, "dripstone_block", 945, rgb(134, 107, 92), 0.16f, 30);
  addRock(out, "moss_block", 946, rgb(89, 109, 45), 0.2f, 160);
  addRock(out, "sponge", 947, rgb(195, 192, 74), 0.26f, 200);
  addRock(out, "wet_sponge", 948, rgb(171, 181, 70), 0.26f, 255);
  addRock(out, "raw_iron_block", 949, rgb(166, 135, 107), 0.2f, 30);
  addRock(out, "raw_copper_block", 950, rgb(154, 105, 79), 0.2f, 30);
  addRock(out, "raw_gold_block", 951, rgb(221, 169, 46), 0.2f, 30);
  addRock(out, "resin_block", 952, rgb(217, 99, 25), 0.12f, 20);
  addRock(out, "honeycomb_block", 953, rgb(229, 148, 29), 0.18f, 60);
  out.push_back(still("coarse_dirt", [](int x, int y) {
    return speckled(x, y, 961, rgb(119, 85, 59), rgb(96, 92, 88), 0.28f);
  }));
  out.push_back(still("rooted_dirt", [](int x, int y) {
    Texel t = dirt(x, y);
    if ((x * 5 + y * 3) % 11 == 0) t.color = rgb(150, 110, 80), t.height = 0.8f;
    return t;
  }));
  out.push_back(
      still("smooth_basalt", [](int x, int y) { return smooth(x, y, 971, rgb(72, 72, 78), 0.08f, 80); }));
  out.push_back(still("polished_blackstone",
                      [](int x, int y) { return polished(rock(972, x, y, rgb(53, 48, 56), 0.12f), x, y); }));
  out.push_back(still("polished_tuff",
                      [](int x, int y) { return polished(rock(973, x, y, rgb(98, 102, 91), 0.12f), x, y); }));
  out.push_back(
      still("coal_block", [](int x, int y) { return smooth(x, y, 974, rgb(22, 22, 24), 0.25f, 90); }));
  out.push_back(
      still("redstone_block", [](int x, int y) { return smooth(x, y, 975, rgb(175, 24, 5), 0.15f, 120); }));
  out.push_back(
      still("amethyst_block", [](int x, int y) { return smooth(x, y, 976, rgb(133, 97, 191), 0.2f, 150); }));
  out.push_back(
      still("blue_ice", [](int x, int y) { return smooth(x, y, 977, rgb(116, 167, 253), 0.06f, 210); }));
  out.push_back(still("crying_obsidian", [](int x, int y) {
    Texel t = smooth(x, y, 978, rgb(32, 10, 60), 0.4f, 220);
    if (hash01(979, x, y) < 0.15f) t.color = rgb(140, 40, 230), t.emission = 120;
    return t;
  }));
  out.push_back(
      still("netherite_block", [](int x, int y) { return metalBlock(x, y, rgb(66, 61, 63), 255, 190); }));
}

void addCoralsAndCoppers(std::vector<GeneratedTexture>& out) {
  const std::array<std::pair<const char*, glm::vec3>, 5> corals = {{{"tube", rgb(49, 87, 207)},
                                                                    {"brain", rgb(207, 91, 159)},
                                                                    {"bubble", rgb(165, 26, 162)},
                                                                    {"fire", rgb(163, 35, 46)},
                                                                    {"horn", rgb(216, 199, 66)}}};
  std::uint64_t seed = 981;
  for (const auto& [kind, colour] : corals) {
    const glm::vec3 c = colour;
    const std::uint64_t s = seed++;
    out.push_back(
        still(std::string(kind) + "_coral_block", [c, s](int x, int y) { return coral(x, y, c, s); }));
    out.push_back(still("dead_" + std::string(kind) + "_coral_block",
                        [s](int x, int y) { return coral(x, y, rgb(130, 123, 119), s); }));
  }
  // Cut copper as its full blocks weather (families.cpp), in four plates.
  out.push_back(
      still("cut_copper", [](int x, int y) { return cutMetal(x, y, rgb(192, 107, 79), 234, 190); }));
  out.push_back(
      still("exposed_cut_copper", [](int x, int y) { return cutMetal(x, y, rgb(160, 120, 95), 234, 150); }));
  out.push_back(still("weathered_cut_copper", [](int x, int y) {
    Texel t = cutMetal(x, y, rgb(110, 150, 110), 234, 100);
    if (fbm(822, static_cast<float>(x), static_cast<float>(y)) > 0.5f)
      t.color = rgb(80, 160, 130) * (x % 8 == 0 || y % 8 == 0 ? 0.75f : 1.0f), t.f0 = 20, t.smoothness = 50;
    return t;
  }));
  out.push_back(still("oxidized_cut_copper", [](int x, int y) {
    Texel t = patina(x, y, rgb(82, 162, 132), 832);
    if (x % 8 == 0 || y % 8 == 0) t.color *= 0.75f, t.height = 0.6f;
    return t;
  }));
}

// Blocks that glow from within: their lit texels carry LabPBR emission.
Texel glowing(int x, int y, std::uint64_t seed, glm::vec3 base, glm::vec3 glow, float share, int emission) {
  Texel t = rock(seed, x, y, base, 0.2f);
  if (fbm(seed + 1, static_cast<float>(x), static_cast<float>(y)) > 1.0f - share)
    t.color = glow, t.emission = emission;
  return t;
}

void addGlowingAndLiving(std::vector<GeneratedTexture>& out) {
  out.push_back(still("magma", [](int x, int y) {
    return glowing(x, y, 1001, rgb(90, 35, 20), rgb(250, 120, 30), 0.35f, 90);
  }));
  out.push_back(still("shroomlight", [](int x, int y) {
    return glowing(x, y, 1002, rgb(240, 150, 70), rgb(255, 220, 140), 0.45f, 200);
  }));
  out.push_back(still("sea_lantern", [](int x, int y) {
    return glowing(x, y, 1003, rgb(170, 200, 190), rgb(235, 250, 245), 0.6f, 220);
  }));
  addRock(out, "nether_wart_block", 1004, rgb(115, 3, 3), 0.25f, 160);
  addRock(out, "warped_wart_block", 1005, rgb(22, 119, 121), 0.25f, 160);
  out.push_back(still("mud", [](int x, int y) { return smooth(x, y, 1006, rgb(60, 57, 60), 0.12f, 150); }));
  out.push_back(still("soul_sand", [](int x, int y) {
    Texel t = rock(1007, x, y, rgb(81, 62, 50), 0.25f);
    if (hash01(1008, x / 3, y / 3) < 0.2f && (x % 3 == 1) && (y % 3 == 1)) t.color *= 0.4f, t.height = 0.2f;
    return t;
  }));
  out.push_back(still("prismarine", [](int x, int y) { return rock(1009, x, y, rgb(99, 156, 151), 0.2f); }));
  out.push_back(still("sculk", [](int x, int y) {
    return glowing(x, y, 1010, rgb(13, 30, 36), rgb(40, 150, 160), 0.15f, 40);
  }));
  out.push_back(still("budding_amethyst", [](int x, int y) {
    Texel t = smooth(x, y, 976, rgb(133, 97, 191), 0.2f, 150);
    if (hash01(1011, x / 4, y / 4) < 0.3f && x % 4 == 2 && y % 4 == 2) t.color = rgb(220, 190, 250);
    return t;
  }));
  addRock(out, "pale_moss_block", 1012, rgb(106, 112, 104), 0.2f, 160);
  addRock(out, "powder_snow", 1013, rgb(248, 253, 253), 0.05f, 200);
  out.push_back(still("tinted_glass", [](int x, int y) {
    Texel t = glass(x, y);
    t.color *= rgb(60, 50, 70) / glm::vec3(0.6f);
    t.alpha = t.alpha > 0.5f ? 1.0f : 0.85f;
    return t;
  }));
}

// Bands across a column's side, rings on its end.
Texel banded(int x, int y, std::uint64_t seed, glm::vec3 colour, int period) {
  Texel t = rock(seed, x, y, colour, 0.1f);
  if (y % period == 0) t.color *= 0.82f, t.height = 0.7f;
  return t;
}
Texel ringed(int x, int y, std::uint64_t seed, glm::vec3 colour) {
  Texel t = rock(seed, x, y, colour, 0.1f);
  const float r = std::max(std::abs(x - 7.5f), std::abs(y - 7.5f));
  if (static_cast<int>(r) % 3 == 0) t.color *= 0.85f;
  return t;
}

void addColumns(std::vector<GeneratedTexture>& out) {
  const auto column = [&](const std::string& side, const std::string& end, std::uint64_t seed,
                          glm::vec3 colour, int period) {
    out.push_back(still(side, [=](int x, int y) { return banded(x, y, seed, colour, period); }));
    out.push_back(still(end, [=](int x, int y) { return ringed(x, y, seed + 1, colour * 1.05f); }));
  };
  column("bone_block_side", "bone_block_top", 1021, rgb(229, 225, 207), 16);
  column("hay_block_side", "hay_block_top", 1023, rgb(166, 136, 38), 4);
  column("quartz_pillar", "quartz_pillar_top", 1025, rgb(235, 230, 222), 16);
  column("purpur_pillar", "purpur_pillar_top", 1027, rgb(171, 129, 171), 16);
  column("basalt_side", "basalt_top", 1029, rgb(80, 81, 86), 3);
  column("polished_basalt_side", "polished_basalt_top", 1031, rgb(99, 98, 100), 8);
  const auto stem = [&](const std::string& name, glm::vec3 bark, glm::vec3 core) {
    out.push_back(still(name, [=](int x, int y) { return logSideOf(x, y, bark); }));
    out.push_back(still(name + "_top", [=](int x, int y) { return logTopOf(x, y, bark, core); }));
    out.push_back(still("stripped_" + name, [=](int x, int y) { return logSideOf(x, y, core * 0.85f); }));
    out.push_back(
        still("stripped_" + name + "_top", [=](int x, int y) { return logTopOf(x, y, core * 0.85f, core); }));
  };
  stem("crimson_stem", rgb(92, 25, 29), rgb(137, 57, 90));
  stem("warped_stem", rgb(57, 58, 78), rgb(58, 142, 140));
  const auto bamboo = [&](const std::string& name, glm::vec3 colour) {
    out.push_back(still(
        name, [=](int x, int y) { return banded(x / 4 * 4 + (x % 4 == 0 ? 0 : 1), y, 1033, colour, 5); }));
    out.push_back(still(name + "_top", [=](int x, int y) { return ringed(x, y, 1034, colour); }));
  };
  bamboo("bamboo_block", rgb(127, 143, 54));
  bamboo("stripped_bamboo_block", rgb(193, 173, 80));
}

}  // namespace

void addBuildingBlockTextures(std::vector<GeneratedTexture>& out) {
  addDyedBlocks(out);
  addPlanks(out);
  addBricksAndTiles(out);
  addStonesAndSoils(out);
  addCoralsAndCoppers(out);
  addGlowingAndLiving(out);
  addColumns(out);
}

}  // namespace terrasol::packgen
