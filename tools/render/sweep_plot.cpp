#include "sweep_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace terrasol {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

// A 3x5 font: 15 bits per glyph, rows top to bottom, each row's leftmost pixel first.
const std::map<char, const char*>& font() {
  static const std::map<char, const char*> glyphs = {
      {'0', "111101101101111"}, {'1', "010110010010111"}, {'2', "111001111100111"}, {'3', "111001111001111"},
      {'4', "101101111001001"}, {'5', "111100111001111"}, {'6', "111100111101111"}, {'7', "111001001001001"},
      {'8', "111101111101111"}, {'9', "111101111001111"}, {'a', "010101111101101"}, {'b', "110101110101110"},
      {'c', "011100100100011"}, {'d', "110101101101110"}, {'e', "111100110100111"}, {'f', "111100110100100"},
      {'g', "011100101101011"}, {'h', "101101111101101"}, {'i', "111010010010111"}, {'j', "001001001101010"},
      {'k', "101101110101101"}, {'l', "100100100100111"}, {'m', "101111111101101"}, {'n', "110101101101101"},
      {'o', "010101101101010"}, {'p', "110101110100100"}, {'q', "010101101110011"}, {'r', "110101110101101"},
      {'s', "011100010001110"}, {'t', "111010010010010"}, {'u', "101101101101111"}, {'v', "101101101101010"},
      {'w', "101101111111101"}, {'x', "101101010101101"}, {'y', "101101010010010"}, {'z', "111001010100111"},
      {'.', "000000000000010"}, {'%', "101001010100101"}, {'+', "000010111010000"}, {'-', "000000111000000"},
      {'/', "001001010100100"}, {'(', "001010010010001"}, {')', "100010010010100"}, {':', "000010000010000"},
      {' ', "000000000000000"},
  };
  return glyphs;
}

class Canvas {
 public:
  explicit Canvas(int w, int h) : image_(w, h) {
    for (std::size_t i = 0; i < image_.rgba.size(); ++i) image_.rgba[i] = 255;
  }
  void dot(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    std::uint8_t* p = image_.pixel(x, y);
    p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
  }
  void box(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) dot(x, y, c);
  }
  void line(int x0, int y0, int x1, int y1, Rgb c, int thickness = 1) {
    const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    for (int err = dx + dy;;) {
      box(x0 - thickness / 2, y0 - thickness / 2, x0 + thickness / 2, y0 + thickness / 2, c);
      if (x0 == x1 && y0 == y1) break;
      const int e2 = 2 * err;
      if (e2 >= dy) err += dy, x0 += sx;
      if (e2 <= dx) err += dx, y0 += sy;
    }
  }
  // Text at scale 2 (6x10 per glyph plus spacing).
  void text(int x, int y, const std::string& s, Rgb c) {
    for (char ch : s) {
      const auto it = font().find(static_cast<char>(std::tolower(static_cast<unsigned char>(ch))));
      const char* bits = it == font().end() ? "111101101101111" : it->second;
      for (int r = 0; r < 5; ++r)
        for (int col = 0; col < 3; ++col) {
          if (bits[r * 3 + col] != '1') continue;
          box(x + col * 2, y + r * 2, x + col * 2 + 1, y + r * 2 + 1, c);
        }
      x += 8;
    }
  }
  Image take() { return std::move(image_); }

 private:
  Image image_;
};

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, v >= 10.0 ? "%.0f" : v >= 1.0 ? "%.1f" : "%.2f", v);
  return s;
}

constexpr Rgb kGroupColours[] = {{220, 50, 40}, {40, 160, 60}, {40, 90, 220}, {230, 140, 20}, {140, 60, 180}};

}  // namespace

Image scatterPlot(const std::vector<PlotPoint>& points, const std::string& xLabel, const std::string& yLabel,
                  const std::vector<std::string>& groupNames, int width, int height) {
  Canvas c(width, height);
  const int left = 80, right = width - 170, top = 30, bottom = height - 60;
  double maxX = 1e-9, maxY = 1e-9;
  for (const auto& p : points) maxX = std::max(maxX, p.x), maxY = std::max(maxY, p.y);
  maxX *= 1.08;
  maxY *= 1.1;
  auto px = [&](double x) { return left + static_cast<int>(std::lround(x / maxX * (right - left))); };
  auto py = [&](double y) { return bottom - static_cast<int>(std::lround(y / maxY * (bottom - top))); };
  const Rgb black{0, 0, 0}, grey{200, 200, 200};
  for (int i = 0; i <= 5; ++i) {
    const int gx = left + (right - left) * i / 5, gy = bottom - (bottom - top) * i / 5;
    c.line(gx, top, gx, bottom, grey);
    c.line(left, gy, right, gy, grey);
    c.text(gx - 12, bottom + 8, number(maxX * i / 5), black);
    c.text(left - 60, gy - 5, number(maxY * i / 5), black);
  }
  c.line(left, bottom, right, bottom, black, 2);
  c.line(left, top, left, bottom, black, 2);
  c.text((left + right) / 2 - static_cast<int>(xLabel.size()) * 4, bottom + 32, xLabel, black);
  c.text(left - 60, 8, yLabel, black);

  std::vector<PlotPoint> front;
  for (const auto& p : points) {
    if (p.marked) front.push_back(p);
  }
  std::sort(front.begin(), front.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
  for (std::size_t i = 1; i < front.size(); ++i) {
    c.line(px(front[i - 1].x), py(front[i - 1].y), px(front[i].x), py(front[i].y), black, 2);
  }
  for (const auto& p : points) {
    const Rgb colour = kGroupColours[static_cast<std::size_t>(p.group) % std::size(kGroupColours)];
    const int x = px(p.x), y = py(p.y);
    if (p.marked) c.box(x - 6, y - 6, x + 6, y + 6, black);
    c.box(x - 4, y - 4, x + 4, y + 4, colour);
  }
  for (std::size_t g = 0; g < groupNames.size(); ++g) {
    const int y = top + 10 + static_cast<int>(g) * 22;
    c.box(right + 20, y, right + 30, y + 10, kGroupColours[g % std::size(kGroupColours)]);
    c.text(right + 38, y, groupNames[g], black);
  }
  const int y = top + 10 + static_cast<int>(groupNames.size()) * 22 + 10;
  c.line(right + 18, y + 5, right + 32, y + 5, black, 2);
  c.text(right + 38, y, "pareto front", black);
  return c.take();
}

}  // namespace terrasol
