#include "texture_parts.h"

#include <cmath>

namespace terrasol::packgen {

void addAll(std::vector<GeneratedTexture>& out, const std::vector<std::pair<std::string, Recipe>>& recipes) {
  for (const auto& [name, recipe] : recipes) out.push_back(still(name, recipe));
}

Texel tinted(Texel t, glm::vec3 colour) {
  t.color = colour;
  return t;
}

Texel glowing(Texel t, int emission) {
  t.emission = emission;
  return t;
}

bool rim(int x, int y, int width) {
  return x < width || y < width || x >= kSize - width || y >= kSize - width;
}

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

Texel copperAt(int x, int y, std::size_t age) {
  const auto& c = kCopper[age].second;
  Texel t = metalBlock(x, y, rgb(c[0], c[1], c[2]), age < 2 ? 234 : 10, age < 2 ? 190 : 80);
  if (age >= 2) t.porosity = 40;
  return t;
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

Texel sign(int x, int y, glm::vec3 base, glm::vec3 ink, const std::array<const char*, 8>& glyph) {
  Texel t = metalBlock(x, y, base, 10, 120);
  const int gx = x / 2, gy = y / 2;
  if (glyph[static_cast<std::size_t>(gy)][gx] == '#') t.color = ink, t.height = 0.9f;
  return t;
}

Texel chiseled(int x, int y, const Texel& ground) {
  Texel t = ground;
  const bool groove = (x == 4 || x == 11) && y > 3 && y < 12;
  const bool groove2 = (y == 4 || y == 11) && x > 3 && x < 12;
  if (rim(x, y) || groove || groove2) t.color *= 0.7f, t.height = 0.5f;
  return t;
}

Texel edged(Texel t, int x, int y, glm::vec3 frame) {
  if (rim(x, y)) t.color = frame, t.height = 0.8f;
  return t;
}

}  // namespace terrasol::packgen
