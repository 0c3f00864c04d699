#include "recipes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "world/noise.h"

namespace terrasol::packgen {

float hash01(std::uint64_t seed, int x, int y, int z) {
  return static_cast<float>(unitFloat(hashCoords(seed, x, y, z)));
}

// Tileable value noise over a 16-texel period, `cells` cells per period.
float tileNoise(std::uint64_t seed, float x, float y, int cells, int frame) {
  const float cx = x * cells / kSize, cy = y * cells / kSize;
  const int x0 = static_cast<int>(std::floor(cx)), y0 = static_cast<int>(std::floor(cy));
  const float fx = cx - x0, fy = cy - y0;
  auto at = [&](int i, int j) {
    return hash01(seed, ((i % cells) + cells) % cells, ((j % cells) + cells) % cells, frame);
  };
  auto smooth = [](float t) { return t * t * (3.0f - 2.0f * t); };
  const float a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * smooth(fx);
  const float b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * smooth(fx);
  return a + (b - a) * smooth(fy);
}

float fbm(std::uint64_t seed, float x, float y, int frame) {
  return 0.5f * tileNoise(seed, x, y, 2, frame) + 0.3f * tileNoise(seed + 1, x, y, 4, frame) +
         0.2f * tileNoise(seed + 2, x, y, 8, frame);
}

Cells voronoi(std::uint64_t seed, int x, int y, int count) {
  Cells c{1e9f, 1e9f, 0};
  for (int i = 0; i < count; ++i) {
    const float px = hash01(seed, i, 0) * kSize, py = hash01(seed, i, 1) * kSize;
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        const float dx = x + 0.5f - (px + ox * kSize), dy = y + 0.5f - (py + oy * kSize);
        const float d = std::sqrt(dx * dx + dy * dy);
        if (d < c.d1)
          c.d2 = c.d1, c.d1 = d, c.id = i;
        else if (d < c.d2)
          c.d2 = d;
      }
  }
  return c;
}

glm::vec3 rgb(int r, int g, int b) {
  return glm::vec3(r, g, b) / 255.0f;
}

Canvas paint(int frames, const std::function<Texel(int x, int y, int frame)>& f) {
  Canvas canvas(static_cast<std::size_t>(kSize * kSize * frames));
  for (int fr = 0; fr < frames; ++fr)
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        canvas[static_cast<std::size_t>((fr * kSize + y) * kSize + x)] = f(x, y, fr);
  return canvas;
}

// --- recipes -------------------------------------------------------------------------------------

Texel rock(std::uint64_t seed, int x, int y, glm::vec3 base, float contrast) {
  const float n = fbm(seed, static_cast<float>(x), static_cast<float>(y));
  Texel t;
  t.color = base * (1.0f - contrast + 2.0f * contrast * n);
  t.height = 0.55f + 0.45f * n;
  t.smoothness = 35 + static_cast<int>(30 * n);
  t.porosity = 20;
  return t;
}

Texel stone(int x, int y) {
  return rock(11, x, y, rgb(125, 125, 125), 0.18f);
}

Texel cobblestone(int x, int y) {
  const Cells c = voronoi(21, x, y, 7);
  const float edge = std::clamp((c.d2 - c.d1) / 2.0f, 0.0f, 1.0f);
  Texel t = rock(22, x, y, rgb(120, 120, 120) * (0.8f + 0.35f * hash01(23, c.id, 0)), 0.12f);
  t.color *= 0.45f + 0.55f * edge;
  t.height = 0.2f + 0.8f * edge;
  t.smoothness = 30;
  return t;
}

Texel dirt(int x, int y) {
  Texel t = rock(31, x, y, rgb(134, 96, 67), 0.2f);
  if (hash01(32, x, y) > 0.9f) t.color = rgb(110, 80, 60), t.height = 0.95f;
  t.porosity = 45;
  t.smoothness = 20;
  return t;
}

Texel ore(int x, int y, std::uint64_t seed, glm::vec3 speck, int specular) {
  return oreIn(x, y, seed, speck, specular, stone);
}

Texel oreIn(int x, int y, std::uint64_t seed, glm::vec3 speck, int specular, Texel (*ground)(int, int)) {
  Texel t = ground(x, y);
  const Cells c = voronoi(seed, x, y, 4);
  if (c.d1 < 1.6f + 0.8f * hash01(seed, c.id, 3)) {
    t.color = speck * (0.8f + 0.4f * hash01(seed, x, y));
    t.height = 1.0f;
    t.f0 = specular;
    t.smoothness = specular >= 230 ? 150 : 70;
    t.porosity = 0;
  }
  return t;
}

Texel metalBlock(int x, int y, glm::vec3 base, int metal, int smoothness) {
  Texel t;
  const bool rim = x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1;
  const bool bevel = x == 1 || y == 1 || x == kSize - 2 || y == kSize - 2;
  const float scratch = fbm(41 + static_cast<std::uint64_t>(metal), x * 0.5f, static_cast<float>(y));
  t.color = base * (rim ? 0.7f : bevel ? 1.12f : 0.95f + 0.1f * scratch);
  t.height = rim ? 0.7f : bevel ? 0.9f : 1.0f;
  t.f0 = metal;
  t.smoothness = rim ? smoothness - 60 : smoothness - static_cast<int>(30 * scratch);
  return t;
}

Texel planks(int x, int y) {
  return planksOf(x, y, rgb(162, 130, 78));
}

Texel planksOf(int x, int y, glm::vec3 colour) {
  const int board = y / 4;
  const float grain = tileNoise(51 + static_cast<std::uint64_t>(board), static_cast<float>(x), y * 4.0f, 8);
  Texel t;
  t.color = colour * (0.82f + 0.25f * grain) * (board % 2 ? 0.95f : 1.0f);
  const bool seam = y % 4 == 3 || (x == (board * 7 + 3) % kSize);
  if (seam) t.color *= 0.6f;
  t.height = seam ? 0.5f : 0.85f + 0.15f * grain;
  t.smoothness = 90;
  return t;
}

Texel logSide(int x, int y) {
  return logSideOf(x, y, rgb(109, 85, 50));
}

Texel logSideOf(int x, int y, glm::vec3 bark) {
  const float stripe = tileNoise(61, x * 1.0f, y * 0.25f, 8);
  Texel t;
  t.color = bark * (0.65f + 0.45f * stripe);
  t.height = 0.4f + 0.6f * stripe;
  t.smoothness = 25;
  t.porosity = 30;
  return t;
}

Texel logTop(int x, int y) {
  return logTopOf(x, y, rgb(109, 85, 50), rgb(176, 143, 88));
}

Texel logTopOf(int x, int y, glm::vec3 bark, glm::vec3 wood) {
  const float dx = x - 7.5f, dy = y - 7.5f, r = std::sqrt(dx * dx + dy * dy);
  Texel t;
  if (std::max(std::abs(dx), std::abs(dy)) > 6.5f) return logSideOf(x, y, bark);
  const float ring = 0.5f + 0.5f * std::cos(r * 2.2f);
  t.color = wood * (0.8f + 0.2f * ring);
  t.height = 0.85f + 0.15f * ring;
  t.smoothness = 60;
  return t;
}

Texel leaves(int x, int y) {
  return leavesOf(x, y, 71);
}

Texel leavesOf(int x, int y, std::uint64_t seed) {
  const float n = fbm(seed, static_cast<float>(x), static_cast<float>(y));
  Texel t;
  t.color = glm::vec3(0.55f + 0.35f * n);  // grey: tinted by the foliage colour
  t.alpha = hash01(seed + 1, x, y) < 0.28f ? 0.0f : 1.0f;
  t.height = 0.5f + 0.5f * n;
  t.smoothness = 70;
  t.porosity = 180;  // B above 64: subsurface scattering
  return t;
}

Texel glass(int x, int y) {
  Texel t;
  const bool frame = x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1;
  const bool streak = (x + y == 6 || x + y == 7 || x + y == 20) && x > 1 && y > 1 && x < 14 && y < 14;
  t.color = frame ? rgb(200, 220, 225) : rgb(230, 245, 250);
  t.alpha = frame || streak ? 1.0f : 0.0f;
  t.smoothness = 250;
  t.f0 = 10;
  return t;
}

Texel plant(int x, int y, std::uint64_t seed, glm::vec3 flower) {
  Texel t;
  t.alpha = 0.0f;
  t.smoothness = 60;
  t.porosity = 150;
  const bool stem = std::abs(x - 7) <= 0 && y > 6;
  const bool leaf = (y == 11 && (x == 6 || x == 8)) || (y == 10 && (x == 5 || x == 9));
  if (flower.r >= 0.0f) {
    const float dx = x - 7.0f, dy = y - 4.5f;
    if (dx * dx + dy * dy < 7.0f)
      t.color = flower * (0.85f + 0.3f * hash01(seed, x, y)), t.alpha = 1.0f;
    else if (stem || leaf)
      t.color = rgb(70, 130, 40), t.alpha = 1.0f;
    return t;
  }
  // Grass blades: grey, tinted by the grass colour.
  const float blade = hash01(seed, x, 0);
  if (y > 16 - 4 - static_cast<int>(blade * 11) && blade > 0.35f)
    t.color = glm::vec3(0.55f + 0.4f * blade), t.alpha = 1.0f;
  return t;
}

Texel glowstone(int x, int y) {
  const Cells c = voronoi(81, x, y, 9);
  const float centre = std::clamp(1.0f - c.d1 / 3.0f, 0.0f, 1.0f);
  Texel t;
  t.color = glm::mix(rgb(140, 100, 50), rgb(255, 236, 160), centre);
  t.height = 0.4f + 0.6f * centre;
  t.smoothness = 100;
  t.emission = static_cast<int>(100 + 154 * centre);
  return t;
}

Texel liquid(int x, int y, int frame, bool lava, bool flowing) {
  const float shift = flowing ? static_cast<float>(frame) * 2.0f : 0.0f;
  const float n = fbm(lava ? 91 : 92, static_cast<float>(x), y - shift, flowing ? 0 : frame);
  Texel t;
  t.height = 0.6f + 0.4f * n;
  if (lava) {
    t.color = glm::mix(rgb(200, 60, 10), rgb(255, 200, 60), n);
    t.emission = 254;
    t.smoothness = 120;
  } else {
    t.color = glm::vec3(0.62f + 0.25f * n);  // grey: tinted by the water colour
    t.alpha = 0.72f;
    t.smoothness = 240;
    t.f0 = 5;  // water: F0 0.02
  }
  return t;
}

// Minecraft's torch layout: the model shows columns 7..8, the flame in rows 6..8 and the stick below.
Texel torch(int x, int y) {
  Texel t;
  t.alpha = 0.0f;
  if ((x == 7 || x == 8) && y >= 9 && y <= 15)
    t.color = rgb(110, 80, 45) * (x == 7 ? 1.0f : 0.8f), t.alpha = 1.0f;
  if ((x == 7 || x == 8) && y >= 6 && y <= 8) {
    t.color = y == 6 ? rgb(255, 240, 170) : rgb(255, 170, 50);
    t.alpha = 1.0f;
    t.emission = 254;
    t.smoothness = 10;
  }
  return t;
}

// A rock's colour with a second mineral speckled through it (granite, diorite).
Texel speckled(int x, int y, std::uint64_t seed, glm::vec3 base, glm::vec3 speck, float amount) {
  Texel t = rock(seed, x, y, base, 0.12f);
  if (hash01(seed + 7, x, y) < amount)
    t.color = speck * (0.85f + 0.3f * hash01(seed + 8, x, y)), t.height = 0.9f;
  return t;
}

// Cut and polished: a bevelled rim, a smooth face that reflects.
Texel polished(Texel t, int x, int y) {
  const bool rim = x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1;
  t.color *= rim ? 0.82f : 1.05f;
  t.height = rim ? 0.75f : 1.0f;
  t.smoothness = rim ? 90 : 180;
  return t;
}

// Bricks laid in courses of `rows` texels, every other course shifted by half a brick.
Texel bricks(int x, int y, std::uint64_t seed, glm::vec3 brick, glm::vec3 mortar, int rows, int width) {
  const int course = y / rows, shift = course % 2 ? width / 2 : 0;
  const bool joint = y % rows == rows - 1 || (x + shift) % width == width - 1;
  if (joint) {
    Texel t = rock(seed + 1, x, y, mortar, 0.1f);
    t.height = 0.45f;
    t.porosity = 60;
    return t;
  }
  Texel t = rock(seed, x, y, brick * (0.9f + 0.2f * hash01(seed, (x + shift) / width, course)), 0.1f);
  t.height = 0.9f + 0.1f * t.height;
  return t;
}

Texel crack(Texel t, int x, int y) {
  if (y == 4 + (x * 3) % 7 / 2 && x > 2 && x < 13) t.color *= 0.45f, t.height = 0.3f;
  return t;
}

Texel moss(Texel t, int x, int y, std::uint64_t seed) {
  if (fbm(seed, static_cast<float>(x), static_cast<float>(y)) > 0.58f) {
    t.color = rgb(88, 112, 55) * (0.8f + 0.3f * hash01(seed, x, y));
    t.porosity = 120;
    t.smoothness = 20;
  }
  return t;
}

Texel smooth(int x, int y, std::uint64_t seed, glm::vec3 colour, float contrast, int smoothness) {
  Texel t = rock(seed, x, y, colour, contrast);
  t.height = 0.9f + 0.1f * t.height;
  t.smoothness = smoothness;
  return t;
}

Texel terracotta(int x, int y, glm::vec3 colour) {
  Texel t = rock(421, x, y, colour, 0.08f);
  t.smoothness = 60;
  t.porosity = 50;
  return t;
}

Texel netherrack(int x, int y) {
  Texel t = rock(941, x, y, rgb(98, 38, 38), 0.3f);
  t.porosity = 80;
  return t;
}

}  // namespace terrasol::packgen
