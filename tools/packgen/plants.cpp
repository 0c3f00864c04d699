// Plants drawn as two crossed planes beyond the first flowers: tulips and the other flowers,
// saplings, mushrooms, the Nether's fungi, roots and sprouts, and seagrass.

#include <array>
#include <cmath>
#include <string>

#include "recipes.h"

namespace terrasol::packgen {
namespace {

// A young tree: a leafy crown over a thin trunk.
Texel sapling(int x, int y, std::uint64_t seed, glm::vec3 leaves) {
  Texel t;
  t.alpha = 0.0f;
  t.smoothness = 40;
  t.porosity = 120;
  const float dx = x - 7.5f, dy = y - 6.0f;
  const float edge = 5.2f + 1.2f * hash01(seed, x, y);
  if (dx * dx * 1.1f + dy * dy < edge * edge && hash01(seed + 1, x, y) > 0.2f) {
    t.color = leaves * (0.75f + 0.4f * hash01(seed + 2, x, y));
    t.alpha = 1.0f;
  } else if ((x == 7 || x == 8) && y >= 9) {
    t.color = rgb(100, 72, 40) * (0.9f + 0.2f * hash01(seed + 3, x, y));
    t.alpha = 1.0f;
  }
  return t;
}

// A mushroom or fungus: a domed cap on a stem, the cap speckled with `dots` where they show.
Texel mushroom(int x, int y, std::uint64_t seed, glm::vec3 cap, glm::vec3 stem, glm::vec3 dots) {
  Texel t;
  t.alpha = 0.0f;
  t.smoothness = 70;
  const float dx = x - 7.5f, dy = y - 9.0f;
  if (y <= 9 && dx * dx / 30.0f + dy * dy / 16.0f < 1.0f) {
    t.color = cap * (0.85f + 0.25f * hash01(seed, x, y));
    if (dots.r >= 0.0f && hash01(seed + 1, x / 2, y / 2) < 0.25f) t.color = dots;
    t.alpha = 1.0f;
  } else if (y > 9 && x >= 6 && x <= 9) {
    t.color = stem * (0.9f + 0.15f * hash01(seed + 2, x, y));
    t.alpha = 1.0f;
  }
  return t;
}

// Blades of one colour: roots, sprouts, seagrass.
Texel blades(int x, int y, std::uint64_t seed, glm::vec3 colour, int tallest) {
  Texel t;
  t.alpha = 0.0f;
  t.porosity = 150;
  const float blade = hash01(seed, x, 0);
  if (y > 16 - 3 - static_cast<int>(blade * static_cast<float>(tallest)) && blade > 0.3f) {
    t.color = colour * (0.7f + 0.45f * blade);
    t.alpha = 1.0f;
  }
  return t;
}

// Each named plant painted by `recipe` in its colour, with seeds counting up from `seed`.
template <std::size_t N>
void addEach(std::vector<GeneratedTexture>& out,
             const std::array<std::pair<const char*, glm::vec3>, N>& plants, std::uint64_t& seed,
             Texel (*recipe)(int, int, std::uint64_t, glm::vec3)) {
  for (const auto& [name, colour] : plants) {
    const glm::vec3 c = colour;
    const std::uint64_t s = seed++;
    out.push_back(still(name, [c, s, recipe](int x, int y) { return recipe(x, y, s, c); }));
  }
}

}  // namespace

void addPlantTextures(std::vector<GeneratedTexture>& out) {
  const std::array<std::pair<const char*, glm::vec3>, 9> flowers = {
      {{"red_tulip", rgb(200, 40, 35)},
       {"orange_tulip", rgb(230, 120, 30)},
       {"white_tulip", rgb(235, 235, 230)},
       {"pink_tulip", rgb(235, 160, 190)},
       {"lily_of_the_valley", rgb(245, 245, 240)},
       {"wither_rose", rgb(35, 30, 30)},
       {"torchflower", rgb(240, 140, 40)},
       {"open_eyeblossom", rgb(245, 150, 60)},
       {"closed_eyeblossom", rgb(120, 120, 135)}}};
  std::uint64_t seed = 1101;
  addEach(out, flowers, seed, plant);
  const std::array<std::pair<const char*, glm::vec3>, 8> saplings = {
      {{"oak_sapling", rgb(60, 120, 30)},
       {"spruce_sapling", rgb(40, 80, 45)},
       {"birch_sapling", rgb(100, 145, 55)},
       {"jungle_sapling", rgb(50, 130, 30)},
       {"acacia_sapling", rgb(105, 130, 30)},
       {"dark_oak_sapling", rgb(40, 90, 20)},
       {"cherry_sapling", rgb(235, 170, 200)},
       {"pale_oak_sapling", rgb(160, 170, 160)}}};
  addEach(out, saplings, seed, sapling);
  const glm::vec3 none(-1.0f);
  out.push_back(still("brown_mushroom", [none](int x, int y) {
    return mushroom(x, y, 1201, rgb(150, 110, 80), rgb(215, 205, 190), none);
  }));
  out.push_back(still("red_mushroom", [](int x, int y) {
    return mushroom(x, y, 1202, rgb(200, 30, 30), rgb(215, 205, 190), rgb(240, 235, 230));
  }));
  out.push_back(still("crimson_fungus", [](int x, int y) {
    return mushroom(x, y, 1203, rgb(160, 30, 35), rgb(230, 120, 40), rgb(240, 170, 60));
  }));
  out.push_back(still("warped_fungus", [](int x, int y) {
    return mushroom(x, y, 1204, rgb(20, 140, 125), rgb(230, 120, 40), rgb(250, 130, 40));
  }));
  out.push_back(
      still("crimson_roots", [](int x, int y) { return blades(x, y, 1205, rgb(150, 20, 40), 11); }));
  out.push_back(
      still("warped_roots", [](int x, int y) { return blades(x, y, 1206, rgb(20, 150, 135), 11); }));
  // Shorter, for flower pots (Minecraft's *_roots_pot).
  out.push_back(
      still("crimson_roots_pot", [](int x, int y) { return blades(x, y, 1209, rgb(150, 20, 40), 8); }));
  out.push_back(
      still("warped_roots_pot", [](int x, int y) { return blades(x, y, 1210, rgb(20, 150, 135), 8); }));
  out.push_back(
      still("nether_sprouts", [](int x, int y) { return blades(x, y, 1207, rgb(20, 160, 140), 6); }));
  out.push_back(still("seagrass", [](int x, int y) { return blades(x, y, 1208, rgb(50, 130, 45), 13); }));
}

}  // namespace terrasol::packgen
