#include "assets/mipmap.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "assets/labpbr.h"
#include "core/srgb.h"

namespace terrasol::mip {
namespace {

const std::array<float, 256>& srgbToLinear() {
  static const auto table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      t[static_cast<std::size_t>(i)] = terrasol::srgbToLinear(static_cast<float>(i) / 255.0f);
    }
    return t;
  }();
  return table;
}

std::uint8_t linearToSrgb(float c) {
  return static_cast<std::uint8_t>(std::lround(terrasol::linearToSrgb(c) * 255.0f));
}

std::uint8_t average(int a, int b, int c, int d) {
  return static_cast<std::uint8_t>((a + b + c + d + 2) / 4);
}

// Calls f(out, the four source texels) for every texel of the halved image.
template <class F>
Image halve(const Image& src, F f) {
  Image out(src.width / 2, src.height / 2);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const std::uint8_t* q[4] = {src.pixel(2 * x, 2 * y), src.pixel(2 * x + 1, 2 * y),
                                  src.pixel(2 * x, 2 * y + 1), src.pixel(2 * x + 1, 2 * y + 1)};
      f(out.pixel(x, y), q);
    }
  return out;
}

// The most common value among four; ties go to the first texel that reaches the top count.
std::uint8_t majority(const std::uint8_t v[4]) {
  int best = 0, bestCount = 0;
  for (int i = 0; i < 4; ++i) {
    const int count = static_cast<int>(std::count(v, v + 4, v[i]));
    if (count > bestCount) best = i, bestCount = count;
  }
  return v[best];
}

// Averages the values of the class (`inClass`) that holds most of the four texels.
template <class InClass>
std::uint8_t averageWithinMajorityClass(const std::uint8_t v[4], InClass inClass) {
  int inside = 0, sumIn = 0, sumOut = 0;
  for (int i = 0; i < 4; ++i) {
    if (inClass(v[i]))
      ++inside, sumIn += v[i];
    else
      sumOut += v[i];
  }
  if (inside >= 2 && (inside > 2 || inClass(v[0])))
    return static_cast<std::uint8_t>((sumIn + inside / 2) / inside);
  return static_cast<std::uint8_t>((sumOut + (4 - inside) / 2) / (4 - inside));
}

}  // namespace

Image halveAlbedo(const Image& src) {
  const auto& lin = srgbToLinear();
  return halve(src, [&](std::uint8_t* out, const std::uint8_t* q[4]) {
    float rgb[3] = {0, 0, 0}, weight = 0.0f, plain[3] = {0, 0, 0};
    int alpha = 0;
    for (int i = 0; i < 4; ++i) {
      const float a = static_cast<float>(q[i][3]) / 255.0f;
      for (int c = 0; c < 3; ++c) {
        rgb[c] += lin[q[i][c]] * a;
        plain[c] += lin[q[i][c]] * 0.25f;
      }
      weight += a;
      alpha += q[i][3];
    }
    for (int c = 0; c < 3; ++c) out[c] = linearToSrgb(weight > 0.0f ? rgb[c] / weight : plain[c]);
    out[3] = static_cast<std::uint8_t>((alpha + 2) / 4);
  });
}

Image halveNormal(const Image& src) {
  return halve(src, [](std::uint8_t* out, const std::uint8_t* q[4]) {
    glm::vec3 sum(0.0f);
    float ao = 0.0f, depth = 0.0f;
    for (int i = 0; i < 4; ++i) {
      const auto t = labpbr::decodeNormal(q[i]);
      sum += t.normal;
      ao += t.ao * 0.25f;
      depth += t.depth * 0.25f;
    }
    // Opposite normals may cancel: encodeNormal turns a zero vector into straight up.
    labpbr::encodeNormal(sum, ao, depth, out);
  });
}

Image halveSpecular(const Image& src) {
  return halve(src, [](std::uint8_t* out, const std::uint8_t* q[4]) {
    const std::uint8_t g[4] = {q[0][1], q[1][1], q[2][1], q[3][1]};
    const std::uint8_t b[4] = {q[0][2], q[1][2], q[2][2], q[3][2]};
    const std::uint8_t a[4] = {q[0][3], q[1][3], q[2][3], q[3][3]};
    out[0] = average(q[0][0], q[1][0], q[2][0], q[3][0]);
    const bool allDielectric = std::all_of(g, g + 4, [](std::uint8_t v) { return v <= 229; });
    out[1] = allDielectric ? average(g[0], g[1], g[2], g[3]) : majority(g);
    out[2] = averageWithinMajorityClass(b, [](std::uint8_t v) { return v <= 64; });
    out[3] = averageWithinMajorityClass(a, [](std::uint8_t v) { return v == 255; });
  });
}

double coverage(const Image& image, const Rect& r) {
  int passed = 0;
  for (int j = r.y; j < r.y + r.h; ++j)
    for (int i = r.x; i < r.x + r.w; ++i) passed += image.pixel(i, j)[3] >= 128;
  return static_cast<double>(passed) / (static_cast<double>(r.w) * r.h);
}

void preserveCoverage(Image& image, const Rect& measure, const Rect& apply, double target) {
  // Binary search on a scale of alpha: coverage only grows with the scale.
  auto coverageWith = [&](double scale) {
    int passed = 0;
    for (int j = measure.y; j < measure.y + measure.h; ++j)
      for (int i = measure.x; i < measure.x + measure.w; ++i) passed += image.pixel(i, j)[3] * scale >= 127.5;
    return static_cast<double>(passed) / (static_cast<double>(measure.w) * measure.h);
  };
  double lo = 0.0, hi = 8.0;
  for (int step = 0; step < 20; ++step) {
    const double mid = 0.5 * (lo + hi);
    (coverageWith(mid) < target ? lo : hi) = mid;
  }
  const double scale = std::abs(coverageWith(lo) - target) < std::abs(coverageWith(hi) - target) ? lo : hi;
  for (int j = apply.y; j < apply.y + apply.h; ++j)
    for (int i = apply.x; i < apply.x + apply.w; ++i) {
      std::uint8_t& alpha = image.pixel(i, j)[3];
      alpha = static_cast<std::uint8_t>(std::min(255.0, std::round(alpha * scale)));
    }
}

}  // namespace terrasol::mip
