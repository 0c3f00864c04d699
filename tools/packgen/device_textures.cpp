// Textures of the made things: redstone's parts, rails, torches, work stations and their faces,
// copper's doors, bulbs, grates, chains and lanterns in every age, candles and shulker boxes in
// sixteen colours, glazed terracotta, heads, cakes, pots and the blocks of the End and of trials.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <string>

#include "recipes.h"

namespace terrasol::packgen {
namespace {

using Recipe = std::function<Texel(int, int)>;

Texel tinted(Texel t, glm::vec3 colour) {
  t.color = colour;
  return t;
}

Texel glowing(Texel t, int emission) {
  t.emission = emission;
  return t;
}

bool rim(int x, int y, int width = 1) {
  return x < width || y < width || x >= kSize - width || y >= kSize - width;
}

// A frame of `frame` round a field of `field`: the faces of machines and tables.
Texel framed(int x, int y, const Texel& field, glm::vec3 frame) {
  if (!rim(x, y, 2)) return field;
  Texel t = rock(1301, x, y, frame, 0.1f);
  t.height = rim(x, y) ? 0.8f : 1.0f;
  return t;
}

Texel hole(int x, int y, int cx, int cy, int r, const Texel& around) {
  const int dx = x - cx, dy = y - cy;
  if (dx * dx + dy * dy > r * r) return around;
  Texel t;
  t.color = rgb(24, 22, 22);
  t.height = 0.15f;
  t.smoothness = 10;
  return t;
}

// Copper in its four ages: bare metal turning to a green patina.
constexpr std::array<std::pair<const char*, std::array<int, 3>>, 4> kCopper = {
    {{"", {192, 107, 79}},
     {"exposed_", {161, 125, 103}},
     {"weathered_", {108, 153, 110}},
     {"oxidized_", {82, 162, 132}}}};

Texel copperAt(int x, int y, std::size_t age) {
  const auto& c = kCopper[age].second;
  Texel t = metalBlock(x, y, rgb(c[0], c[1], c[2]), age < 2 ? 234 : 10, age < 2 ? 190 : 80);
  if (age >= 2) t.porosity = 40;
  return t;
}

// A rail: two iron rails over wooden sleepers, the rest empty; `curve` bends it from south to east.
Texel rail(int x, int y, bool curve, glm::vec3 railColour, bool powered) {
  const float u = static_cast<float>(x) + 0.5f, v = static_cast<float>(y) + 0.5f;
  // Along the track and across it, for straight and curved rails (the curve centred on the
  // south-east corner).
  float along = v, across = u;
  if (curve) {
    const float dx = 16.0f - u, dy = 16.0f - v;
    across = 16.0f - std::sqrt(dx * dx + dy * dy);
    along = std::atan2(dy, dx) * 10.0f;
  }
  const bool railHere = std::abs(across - 3.5f) < 1.0f || std::abs(across - 12.5f) < 1.0f;
  const bool sleeper = std::fmod(std::abs(along) + 16.0f, 4.0f) < 2.0f && across > 1.0f && across < 15.0f;
  if (railHere) {
    Texel t = metalBlock(x, y, railColour, 230, 170);
    if (powered) t.emission = 200;
    return t;
  }
  if (sleeper) return planksOf(x, y, rgb(110, 80, 50));
  return clear();
}

Texel dust(int x, int y, bool line) {
  const bool on = line ? (x >= 6 && x <= 9) : (std::abs(x - 7.5f) + std::abs(y - 7.5f) < 5.0f);
  if (!on) return clear();
  Texel t;
  t.color = rgb(200, 20, 10) * (0.75f + 0.35f * hash01(1311, x, y));
  t.emission = 120;
  t.smoothness = 60;
  return t;
}

// A torch with a coloured head: Minecraft's torch layout (torch() in recipes.cpp) with another flame.
Texel torchOf(int x, int y, glm::vec3 flame, bool lit) {
  Texel t = torch(x, y);
  if (t.emission != 255) {
    t.color = lit ? flame : flame * 0.35f;
    t.emission = lit ? 254 : 255;
  }
  return t;
}

Texel lever(int x, int y) {
  if (x < 7 || x > 8 || y < 6) return clear();
  return planksOf(x, y, rgb(120, 90, 55));
}

// Repeaters and comparators from above: smooth stone with a redstone trace along the middle.
Texel diodeTop(int x, int y, bool on) {
  Texel t = smooth(x, y, 1321, rgb(160, 160, 160), 0.05f, 120);
  if (x >= 7 && x <= 8 && y > 1 && y < 14)
    t.color = on ? rgb(240, 40, 20) : rgb(110, 20, 15), t.emission = on ? 150 : 255;
  return t;
}

Texel daylightTop(int x, int y, bool inverted) {
  Texel t =
      (x / 4 + y / 4) % 2
          ? tinted(rock(1331, x, y, rgb(0, 0, 0), 0.1f), inverted ? rgb(70, 90, 140) : rgb(190, 180, 150))
          : tinted(rock(1332, x, y, rgb(0, 0, 0), 0.1f), inverted ? rgb(40, 50, 90) : rgb(120, 140, 170));
  t.smoothness = 200;
  return framed(x, y, t, rgb(130, 100, 60));
}

// The faces of a piston: its plank head, the casing round it, its inside.
Texel pistonSide(int x, int y) {
  if (y < 4) return planksOf(x, y, rgb(162, 130, 78));
  Texel t = cobblestone(x, y);
  if (x >= 6 && x <= 9 && y >= 4) t.color = rgb(150, 140, 120), t.height = 0.9f;  // the rod
  return t;
}

// A cube of sixteen texels showing a single bold sign: the operator's blocks, note blocks...
Texel sign(int x, int y, glm::vec3 base, glm::vec3 ink, const std::array<const char*, 8>& glyph) {
  Texel t = metalBlock(x, y, base, 10, 120);
  const int gx = x / 2, gy = y / 2;
  if (glyph[static_cast<std::size_t>(gy)][gx] == '#') t.color = ink, t.height = 0.9f;
  return t;
}

constexpr std::array<const char*, 8> kArrow = {"........", "...##...", "..####..", ".##..##.",
                                               "...##...", "...##...", "...##...", "........"};
constexpr std::array<const char*, 8> kNote = {"........", "....###.", "....#.#.", "....#...",
                                              "..###...", ".####...", "..##....", "........"};
constexpr std::array<const char*, 8> kRing = {"........", "..####..", ".#....#.", ".#.##.#.",
                                              ".#.##.#.", ".#....#.", "..####..", "........"};
constexpr std::array<const char*, 8> kPlain = {"........", "........", "........", "........",
                                               "........", "........", "........", "........"};

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

Texel cake(int x, int y, int face) {  // 0 top, 1 side, 2 bottom, 3 inside
  if (face == 0) {
    Texel t = smooth(x, y, 1371, rgb(240, 236, 228), 0.04f, 90);
    if (hash01(1372, x, y) < 0.08f) t.color = rgb(200, 30, 30);  // cherries
    return t;
  }
  if (face == 2) return smooth(x, y, 1373, rgb(180, 120, 70), 0.08f, 40);
  Texel t = rock(1374, x, y, rgb(200, 150, 90), 0.08f);
  if (y >= 8 && y <= 9) t.color = rgb(220, 60, 60);      // jam
  if (y < 8 && face == 1) t.color = rgb(240, 236, 228);  // icing
  return t;
}

// Links of a chain down the middle three texels, where Minecraft's chain model reads them.
Texel chain(int x, int y, glm::vec3 metal) {
  const int u = x - 6, v = y % 6;
  const bool link = v < 3 ? (u == 0 || u == 3) && v != 0 : u >= 0 && u <= 3 && (v == 3 || v == 5);
  if (!link) return clear();
  return metalBlock(x, y, metal, 230, 150);
}

Texel bars(int x, int y, glm::vec3 metal) {
  // Bars at the edges and down the middle, where the pane templates' posts and sides read them.
  if (x % 7 > 1 && y != 0 && y != 15) return clear();
  return metalBlock(x, y, metal, 230, 160);
}

Texel grate(int x, int y, std::size_t age) {
  if (x % 4 != 0 && y % 4 != 0 && !rim(x, y)) return clear();
  return copperAt(x, y, age);
}

Texel chiseled(int x, int y, const Texel& ground) {
  Texel t = ground;
  const bool groove = (x == 4 || x == 11) && y > 3 && y < 12;
  const bool groove2 = (y == 4 || y == 11) && x > 3 && x < 12;
  if (rim(x, y) || groove || groove2) t.color *= 0.7f, t.height = 0.5f;
  return t;
}

Texel bulb(int x, int y, std::size_t age, bool lit, bool powered) {
  if (x >= 4 && x <= 11 && y >= 4 && y <= 11) {
    Texel t;
    t.color = lit ? rgb(255, 220, 150) : rgb(90, 70, 60);
    t.emission = lit ? 250 : 255;
    t.smoothness = 200;
    if (powered && x >= 7 && x <= 8 && y >= 7 && y <= 8) t.color = rgb(230, 30, 20);
    return t;
  }
  return copperAt(x, y, age);
}

void addAll(std::vector<GeneratedTexture>& out, const std::vector<std::pair<std::string, Recipe>>& recipes) {
  for (const auto& [name, recipe] : recipes) out.push_back(still(name, recipe));
}

void addRedstoneTextures(std::vector<GeneratedTexture>& out) {
  const glm::vec3 iron = rgb(170, 170, 175), gold = rgb(230, 190, 60);
  addAll(
      out,
      {{"rail", [=](int x, int y) { return rail(x, y, false, iron, false); }},
       {"rail_corner", [=](int x, int y) { return rail(x, y, true, iron, false); }},
       {"powered_rail", [=](int x, int y) { return rail(x, y, false, gold, false); }},
       {"powered_rail_on",
        [=](int x, int y) { return rail(x, y, false, gold * glm::vec3(1, 0.6f, 0.5f), true); }},
       {"detector_rail", [=](int x, int y) { return rail(x, y, false, rgb(150, 140, 140), false); }},
       {"detector_rail_on", [=](int x, int y) { return rail(x, y, false, rgb(200, 90, 80), true); }},
       {"activator_rail", [=](int x, int y) { return rail(x, y, false, rgb(140, 110, 100), false); }},
       {"activator_rail_on", [=](int x, int y) { return rail(x, y, false, rgb(210, 80, 60), true); }},
       {"redstone_dust_dot", [](int x, int y) { return dust(x, y, false); }},
       {"redstone_dust_line0", [](int x, int y) { return dust(x, y, true); }},
       {"redstone_torch", [](int x, int y) { return torchOf(x, y, rgb(255, 60, 30), true); }},
       {"redstone_torch_off", [](int x, int y) { return torchOf(x, y, rgb(255, 60, 30), false); }},
       {"soul_torch", [](int x, int y) { return torchOf(x, y, rgb(90, 220, 235), true); }},
       {"copper_torch", [](int x, int y) { return torchOf(x, y, rgb(120, 240, 140), true); }},
       {"lever", lever},
       {"repeater", [](int x, int y) { return diodeTop(x, y, false); }},
       {"repeater_on", [](int x, int y) { return diodeTop(x, y, true); }},
       {"comparator", [](int x, int y) { return hole(x, y, 7, 7, 2, diodeTop(x, y, false)); }},
       {"comparator_on", [](int x, int y) { return hole(x, y, 7, 7, 2, diodeTop(x, y, true)); }},
       {"daylight_detector_top", [](int x, int y) { return daylightTop(x, y, false); }},
       {"daylight_detector_inverted_top", [](int x, int y) { return daylightTop(x, y, true); }},
       {"daylight_detector_side", [](int x, int y) { return planksOf(x, y, rgb(130, 100, 60)); }},
       {"tripwire",
        [](int x, int y) {
          return x == 7 || x == 8 ? tinted(smooth(x, y, 1381, rgb(0, 0, 0), 0.0f, 40), rgb(220, 220, 220))
                                  : clear();
        }},
       {"piston_top", [](int x, int y) { return planksOf(x, y, rgb(162, 130, 78)); }},
       {"piston_top_sticky",
        [](int x, int y) {
          Texel t = planksOf(x, y, rgb(162, 130, 78));
          if (!rim(x, y, 3))
            t.color = rgb(110, 170, 90) * (0.9f + 0.2f * hash01(1382, x, y)), t.smoothness = 220;
          return t;
        }},
       {"piston_side", pistonSide},
       {"piston_bottom", [](int x, int y) { return hole(x, y, 7, 7, 2, cobblestone(x, y)); }},
       {"piston_inner", [](int x, int y) { return hole(x, y, 7, 7, 3, cobblestone(x, y)); }},
       {"dispenser_front", [](int x, int y) { return hole(x, y, 7, 7, 3, cobblestone(x, y)); }},
       {"dropper_front", [](int x, int y) { return hole(x, y, 7, 9, 2, cobblestone(x, y)); }},
       {"observer_front",
        [](int x, int y) {
          Texel t = cobblestone(x, y);
          if (y >= 6 && y <= 9 && (x / 3) % 2 == 0) t.color = rgb(40, 40, 45), t.height = 0.3f;
          return t;
        }},
       {"observer_side", [](int x, int y) { return chiseled(x, y, cobblestone(x, y)); }},
       {"observer_back", [](int x, int y) { return hole(x, y, 7, 7, 2, cobblestone(x, y)); }},
       {"observer_back_on",
        [](int x, int y) {
          return glowing(
              tinted(cobblestone(x, y),
                     (x - 7) * (x - 7) + (y - 7) * (y - 7) <= 4 ? rgb(240, 40, 20) : cobblestone(x, y).color),
              255);
        }},
       {"redstone_lamp",
        [](int x, int y) { return framed(x, y, rock(1383, x, y, rgb(120, 70, 40), 0.2f), rgb(90, 60, 40)); }},
       {"redstone_lamp_on",
        [](int x, int y) {
          return framed(x, y, glowing(rock(1384, x, y, rgb(250, 200, 120), 0.15f), 240), rgb(150, 100, 60));
        }},
       {"note_block", [](int x, int y) { return sign(x, y, rgb(110, 70, 45), rgb(60, 35, 20), kNote); }},
       {"jukebox_side",
        [](int x, int y) { return framed(x, y, planksOf(x, y, rgb(120, 80, 55)), rgb(80, 55, 35)); }},
       {"jukebox_top",
        [](int x, int y) {
          return hole(x, y, 7, 7, 3, framed(x, y, planksOf(x, y, rgb(120, 80, 55)), rgb(80, 55, 35)));
        }},
       {"target_side",
        [](int x, int y) {
          const float r = std::hypot(x - 7.5f, y - 7.5f);
          Texel t =
              rock(1385, x, y, static_cast<int>(r / 2.2f) % 2 ? rgb(230, 225, 215) : rgb(200, 40, 40), 0.06f);
          return t;
        }},
       {"target_top", [](int x, int y) { return rock(1386, x, y, rgb(200, 190, 120), 0.15f); }},
       {"tnt_side",
        [](int x, int y) {
          Texel t = rock(1387, x, y, rgb(200, 50, 40), 0.1f);
          if (y >= 5 && y <= 10) t.color = rgb(230, 228, 220);
          if (y >= 6 && y <= 9 && x % 4 == 1) t.color = rgb(30, 30, 30);
          return t;
        }},
       {"tnt_top",
        [](int x, int y) { return hole(x, y, 7, 7, 1, rock(1388, x, y, rgb(190, 60, 45), 0.1f)); }},
       {"tnt_bottom", [](int x, int y) { return rock(1389, x, y, rgb(170, 50, 40), 0.1f); }},
       {"crafter",
        [](int x, int y) { return hole(x, y, 7, 7, 2, framed(x, y, cobblestone(x, y), rgb(90, 80, 75))); }},
       {"hopper_outside", [](int x, int y) { return metalBlock(x, y, rgb(70, 70, 75), 230, 140); }}});
  for (const std::string kind : {"command_block", "repeating_command_block", "chain_command_block"}) {
    const glm::vec3 base = kind == "command_block"             ? rgb(190, 130, 90)
                           : kind == "repeating_command_block" ? rgb(120, 90, 190)
                                                               : rgb(110, 170, 150);
    addAll(out, {{kind + "_front", [=](int x, int y) { return sign(x, y, base, rgb(30, 30, 30), kRing); }},
                 {kind + "_back", [=](int x, int y) { return sign(x, y, base, rgb(30, 30, 30), kPlain); }},
                 {kind + "_side", [=](int x, int y) { return sign(x, y, base, rgb(30, 30, 30), kArrow); }}});
  }
  addAll(out, {{"test_block",
                [](int x, int y) { return sign(x, y, rgb(60, 90, 120), rgb(230, 230, 230), kRing); }},
               {"test_instance_block",
                [](int x, int y) { return sign(x, y, rgb(60, 120, 90), rgb(230, 230, 230), kArrow); }}});
}

void addWorkshopTextures(std::vector<GeneratedTexture>& out) {
  const glm::vec3 dark = rgb(60, 60, 65);
  addAll(
      out,
      {{"cauldron_side", [=](int x, int y) { return metalBlock(x, y, dark, 230, 130); }},
       {"anvil", [=](int x, int y) { return metalBlock(x, y, rgb(70, 70, 72), 230, 120); }},
       {"anvil_top", [=](int x, int y) { return metalBlock(x, y, rgb(90, 90, 92), 230, 200); }},
       {"chipped_anvil_top",
        [=](int x, int y) { return crack(metalBlock(x, y, rgb(90, 90, 92), 230, 180), x, y); }},
       {"damaged_anvil_top",
        [=](int x, int y) {
          return crack(crack(metalBlock(x, y, rgb(85, 85, 88), 230, 150), x, y), 15 - x, y);
        }},
       {"enchanting_table_top",
        [](int x, int y) {
          Texel t = rock(1401, x, y, rgb(40, 30, 60), 0.2f);
          if (!rim(x, y, 3)) t.color = rgb(170, 30, 40) * (0.85f + 0.2f * hash01(1402, x, y));  // the cloth
          return t;
        }},
       {"end_portal_frame_top",
        [](int x, int y) {
          return hole(x, y, 7, 7, 4,
                      framed(x, y, rock(1403, x, y, rgb(70, 110, 100), 0.15f), rgb(220, 220, 170)));
        }},
       {"end_portal_frame_side",
        [](int x, int y) {
          Texel t = rock(1404, x, y, rgb(220, 220, 170), 0.1f);
          if (y < 4) t.color = rgb(70, 110, 100);
          return t;
        }},
       {"end_portal_frame_eye",
        [](int x, int y) {
          return glowing(hole(x, y, 7, 7, 2, smooth(x, y, 1405, rgb(60, 150, 100), 0.2f, 220)), 180);
        }},
       {"end_portal",
        [](int x, int y) {
          Texel t = smooth(x, y, 1406, rgb(10, 20, 25), 0.2f, 230);
          if (hash01(1407, x, y) < 0.06f) t.color = rgb(140, 230, 210), t.emission = 220;
          return t;
        }},
       {"end_gateway",
        [](int x, int y) {
          Texel t = smooth(x, y, 1408, rgb(15, 15, 30), 0.2f, 230);
          if (hash01(1409, x, y) < 0.08f) t.color = rgb(210, 180, 250), t.emission = 220;
          return t;
        }},
       {"beacon",
        [](int x, int y) {
          return glowing(framed(x, y, smooth(x, y, 1410, rgb(120, 230, 230), 0.1f, 230), rgb(200, 240, 240)),
                         200);
        }},
       {"conduit",
        [](int x, int y) {
          return framed(x, y, glowing(smooth(x, y, 1411, rgb(80, 170, 200), 0.1f, 200), 150),
                        rgb(150, 120, 90));
        }},
       {"dragon_egg",
        [](int x, int y) {
          Texel t = rock(1412, x, y, rgb(20, 10, 30), 0.3f);
          if (hash01(1413, x, y) < 0.1f) t.color = rgb(140, 60, 180);
          t.smoothness = 180;
          return t;
        }},
       {"scaffolding_top",
        [](int x, int y) {
          Texel t = planksOf(x, y, rgb(200, 170, 100));
          if (rim(x, y, 2)) t.color *= 0.75f;
          return t;
        }},
       {"scaffolding_side",
        [](int x, int y) {
          if (!rim(x, y, 2) && std::abs(x - y) > 1) return clear();
          return planksOf(x, y, rgb(190, 160, 95));
        }},
       {"scaffolding_bottom",
        [](int x, int y) { return rim(x, y, 2) ? planksOf(x, y, rgb(180, 150, 90)) : clear(); }},
       {"end_rod",
        [](int x, int y) { return glowing(smooth(x, y, 1421, rgb(240, 235, 225), 0.05f, 200), 230); }},
       {"heavy_core",
        [](int x, int y) { return chiseled(x, y, metalBlock(x, y, rgb(80, 85, 95), 230, 170)); }},
       {"cake_top", [](int x, int y) { return cake(x, y, 0); }},
       {"cake_side", [](int x, int y) { return cake(x, y, 1); }},
       {"cake_bottom", [](int x, int y) { return cake(x, y, 2); }},
       {"cake_inner", [](int x, int y) { return cake(x, y, 3); }},
       {"flower_pot", [](int x, int y) { return terracotta(x, y, rgb(150, 80, 55)); }},
       {"composter_compost", [](int x, int y) { return rock(1414, x, y, rgb(90, 70, 40), 0.3f); }},
       {"composter_ready",
        [](int x, int y) {
          Texel t = rock(1415, x, y, rgb(90, 70, 40), 0.3f);
          if (hash01(1416, x, y) < 0.15f) t.color = rgb(230, 230, 220);
          return t;
        }},
       {"iron_door_bottom", [](int x, int y) { return doorBottom(x, y, rgb(200, 200, 205)); }},
       {"iron_door_top", [](int x, int y) { return doorTop(x, y, rgb(200, 200, 205)); }},
       {"iron_trapdoor", [](int x, int y) { return trapdoor(x, y, rgb(200, 200, 205)); }},
       {"iron_chain", [](int x, int y) { return chain(x, y, rgb(70, 75, 85)); }},
       {"iron_bars", [](int x, int y) { return bars(x, y, rgb(150, 150, 155)); }},
       {"soul_lantern",
        [](int x, int y) {
          Texel t = lantern(x, y);
          if (t.emission != 255) t.color = rgb(110, 220, 235);
          return t;
        }},
       {"spawner",
        [](int x, int y) {
          return x % 4 == 0 || y % 4 == 0 ? metalBlock(x, y, rgb(40, 45, 55), 230, 120) : clear();
        }},
       {"trial_spawner_side_inactive",
        [](int x, int y) { return x % 4 == 0 || y % 4 == 0 ? copperAt(x, y, 2) : clear(); }},
       {"trial_spawner_top_inactive", [](int x, int y) { return hole(x, y, 7, 7, 3, copperAt(x, y, 2)); }},
       {"trial_spawner_bottom", [](int x, int y) { return copperAt(x, y, 3); }},
       {"vault_front_off",
        [](int x, int y) { return hole(x, y, 7, 8, 3, chiseled(x, y, copperAt(x, y, 2))); }},
       {"vault_side_off", [](int x, int y) { return chiseled(x, y, copperAt(x, y, 2)); }},
       {"vault_top", [](int x, int y) { return copperAt(x, y, 3); }},
       {"vault_bottom", [](int x, int y) { return copperAt(x, y, 1); }},
       {"respawn_anchor_top_off",
        [](int x, int y) { return hole(x, y, 7, 7, 4, rock(1417, x, y, rgb(30, 25, 40), 0.2f)); }},
       {"respawn_anchor_top",
        [](int x, int y) {
          Texel t = rock(1418, x, y, rgb(30, 25, 40), 0.2f);
          if ((x - 7) * (x - 7) + (y - 7) * (y - 7) <= 16) t.color = rgb(160, 80, 240), t.emission = 240;
          return t;
        }},
       {"respawn_anchor_side0",
        [](int x, int y) { return framed(x, y, rock(1419, x, y, rgb(30, 25, 40), 0.2f), rgb(60, 50, 70)); }},
       {"respawn_anchor_side4",
        [](int x, int y) {
          Texel t = framed(x, y, rock(1419, x, y, rgb(30, 25, 40), 0.2f), rgb(60, 50, 70));
          if (y >= 2 && y <= 3 && x % 4 == 2) t.color = rgb(200, 120, 255), t.emission = 220;
          return t;
        }},
       {"respawn_anchor_bottom", [](int x, int y) { return rock(1420, x, y, rgb(25, 20, 35), 0.2f); }},
       {"lodestone_top",
        [](int x, int y) { return hole(x, y, 7, 7, 2, framed(x, y, stone(x, y), rgb(60, 60, 60))); }},
       {"lodestone_side", [](int x, int y) { return chiseled(x, y, stone(x, y)); }}});
  for (std::size_t age = 0; age < kCopper.size(); ++age) {
    const std::string a = kCopper[age].first;
    const auto& c = kCopper[age].second;
    const glm::vec3 metal = rgb(c[0], c[1], c[2]);
    addAll(out, {{a + "copper_door_bottom", [=](int x, int y) { return doorBottom(x, y, metal); }},
                 {a + "copper_door_top", [=](int x, int y) { return doorTop(x, y, metal); }},
                 {a + "copper_trapdoor", [=](int x, int y) { return trapdoor(x, y, metal); }},
                 {a + "copper_grate", [=](int x, int y) { return grate(x, y, age); }},
                 {a + "chiseled_copper", [=](int x, int y) { return chiseled(x, y, copperAt(x, y, age)); }},
                 {a + "copper_chain", [=](int x, int y) { return chain(x, y, metal); }},
                 {a + "copper_bars", [=](int x, int y) { return bars(x, y, metal); }},
                 {a + "copper_lantern", [=](int x, int y) {
                    Texel t = lantern(x, y);
                    if (t.emission != 255)
                      t.color = rgb(140, 250, 160);
                    else if (t.alpha > 0.0f)
                      t.color = metal * 0.8f;
                    return t;
                  }}});
    for (const bool lit : {false, true})
      for (const bool powered : {false, true})
        out.push_back(still(a + "copper_bulb" + (lit ? "_lit" : "") + (powered ? "_powered" : ""),
                            [=](int x, int y) { return bulb(x, y, age, lit, powered); }));
  }
}

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

}  // namespace

void addDeviceTextures(std::vector<GeneratedTexture>& out) {
  addRedstoneTextures(out);
  addWorkshopTextures(out);
  addColouredTextures(out);
  addFrontTextures(out);
  addFaceTextures(out);
}

}  // namespace terrasol::packgen
