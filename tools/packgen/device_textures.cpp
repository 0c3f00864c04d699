// Textures of the made things: redstone's parts, rails, torches, work stations, copper's doors,
// bulbs, grates, chains and lanterns in every age, cakes, pots and the blocks of the End and of
// trials. The coloured and fronted blocks' faces come from face_textures.cpp.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <string>

#include "texture_parts.h"

namespace terrasol::packgen {
namespace {

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
       // The hook's iron: a worn grey metal.
       {"tripwire_hook", [](int x, int y) { return metalBlock(x, y, rgb(160, 160, 165), 230, 150); }},
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

}  // namespace

void addDeviceTextures(std::vector<GeneratedTexture>& out) {
  addRedstoneTextures(out);
  addWorkshopTextures(out);
  addColouredTextures(out);
  addFrontTextures(out);
  addFaceTextures(out);
}

}  // namespace terrasol::packgen
