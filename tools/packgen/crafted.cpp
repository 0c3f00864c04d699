#include <algorithm>
#include <cmath>

#include "recipes.h"

namespace terrasol::packgen {
namespace {

// Boards running up the texture, for doors and trapdoors.
Texel verticalBoards(int x, int y, glm::vec3 wood) {
  Texel t = planksOf(y, x, wood);
  t.color *= 0.95f;
  return t;
}

Texel ladder(int x, int y) {
  const bool rail = x == 2 || x == 3 || x == 12 || x == 13;
  const bool rung = (y % 4 == 1 || y % 4 == 2) && x > 3 && x < 12;
  if (!rail && !rung) return clear();
  Texel t = planks(x, y % 4 + (rail ? 0 : 4));
  t.color *= rung && y % 4 == 2 ? 0.8f : 1.0f;
  t.height = rail ? 1.0f : 0.85f;
  return t;
}

bool doorFrame(int x, int y) {
  return x <= 1 || x >= 14 || y <= 1 || y >= 14;
}

}  // namespace

Texel doorBottom(int x, int y, glm::vec3 wood) {
  Texel t = verticalBoards(x, y, wood);
  if (doorFrame(x, y)) t.color *= 0.8f, t.height = 1.0f;
  if (!doorFrame(x, y) && (x == 7 || x == 8) && y > 3 && y < 12)
    t.color *= 0.7f, t.height = 0.6f;  // a cross brace
  return t;
}

Texel doorTop(int x, int y, glm::vec3 wood) {
  const bool window = y >= 3 && y <= 7 && ((x >= 3 && x <= 6) || (x >= 9 && x <= 12));
  if (window) return clear();
  Texel t = verticalBoards(x, y, wood);
  if (doorFrame(x, y) || x == 7 || x == 8 || y == 8) t.color *= 0.8f, t.height = 1.0f;
  return t;
}

Texel trapdoor(int x, int y, glm::vec3 wood) {
  const bool hole =
      ((x >= 3 && x <= 6) || (x >= 9 && x <= 12)) && ((y >= 3 && y <= 6) || (y >= 9 && y <= 12));
  if (hole) return clear();
  Texel t = verticalBoards(x, y, wood);
  if (doorFrame(x, y)) t.color *= 0.8f, t.height = 1.0f;
  return t;
}

namespace {

Texel paneEdge(int x, int y) {
  Texel t = glass(0, y);  // the glass's frame colour, along the pane's edge
  t.alpha = 1.0f;
  t.color *= x == 7 || x == 8 ? 1.0f : 0.92f;
  return t;
}

// Smooth stone with a bevelled rim: the furnace's casing.
Texel casing(int x, int y) {
  Texel t = rock(211, x, y, rgb(110, 110, 110), 0.1f);
  if (x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1) t.color *= 0.75f, t.height = 0.8f;
  return t;
}

Texel furnaceFront(int x, int y) {
  if (x >= 3 && x <= 12 && y >= 8 && y <= 13) {
    Texel t;
    t.color = rgb(25, 22, 20) * (y >= 12 ? 1.6f : 1.0f);
    t.height = 0.2f;
    t.smoothness = 10;
    return t;
  }
  Texel t = cobblestone(x, y);
  if (y == 3 || y == 4) t.color *= 0.7f, t.height = 0.5f;  // a groove above the mouth
  return t;
}

// Tilled soil: furrows across the texture, darker when moist.
Texel farmland(int x, int y, bool moist) {
  Texel t = dirt(x, y);
  const bool furrow = y % 4 == 0;
  t.color *= (furrow ? 0.7f : 1.0f) * (moist ? 0.62f : 0.95f);
  t.height = furrow ? 0.4f : t.height;
  t.smoothness = moist ? 70 : 20;
  t.porosity = moist ? 200 : 60;
  return t;
}

Texel pathTop(int x, int y) {
  Texel t = rock(221, x, y, rgb(148, 121, 65), 0.12f);
  t.height = 0.7f + 0.3f * fbm(222, static_cast<float>(x), static_cast<float>(y));
  t.porosity = 40;
  t.smoothness = 30;
  return t;
}

}  // namespace

void addCraftedTextures(std::vector<GeneratedTexture>& out) {
  out.push_back(still("ladder", ladder));
  const glm::vec3 oak = rgb(162, 130, 78);  // planks()'s
  out.push_back(still("oak_door_bottom", [oak](int x, int y) { return doorBottom(x, y, oak); }));
  out.push_back(still("oak_door_top", [oak](int x, int y) { return doorTop(x, y, oak); }));
  out.push_back(still("oak_trapdoor", [oak](int x, int y) { return trapdoor(x, y, oak); }));
  out.push_back(still("glass_pane_top", paneEdge));
  out.push_back(still("furnace_front", furnaceFront));
  out.push_back(still("furnace_side", casing));
  out.push_back(still("furnace_top", [](int x, int y) { return stone(x, y); }));
  out.push_back(still("farmland", [](int x, int y) { return farmland(x, y, false); }));
  out.push_back(still("farmland_moist", [](int x, int y) { return farmland(x, y, true); }));
  out.push_back(still("dirt_path_top", pathTop));
  out.push_back(still("dirt_path_side", [](int x, int y) { return y < 2 ? pathTop(x, y) : dirt(x, y); }));
}

}  // namespace terrasol::packgen
