#include "scene_render/lod_error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <vector>

namespace terrasol {
namespace {

// The largest channel's difference, 0..1.
double pixelError(const Image& a, const Image& b, int x, int y) {
  const std::uint8_t* p = a.pixel(x, y);
  const std::uint8_t* q = b.pixel(x, y);
  int most = 0;
  for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(p[c]) - int(q[c])));
  return most / 255.0;
}

struct Stats {
  double mean = 0.0, p99 = 0.0;
};
Stats statsOf(std::vector<double> errors) {
  if (errors.empty()) return {};
  double sum = 0.0;
  for (const double e : errors) sum += e;
  const auto at = static_cast<std::ptrdiff_t>(std::floor(0.99 * static_cast<double>(errors.size() - 1)));
  std::nth_element(errors.begin(), errors.begin() + at, errors.end());
  return {sum / static_cast<double>(errors.size()), errors[static_cast<std::size_t>(at)]};
}

// A frame's pixels as seen from its camera: sky, or the horizontal distance to the surface.
class Surfaces {
 public:
  explicit Surfaces(const RenderedFrame& f) : f_(f) {}
  bool sky(int x, int y) const { return depth(x, y) >= 1.0f; }
  double horizontal(int x, int y) const {
    const glm::ivec2 size = f_.pixels.size;
    const glm::vec4 ndc((x + 0.5f) / size.x * 2.0f - 1.0f, (size.y - 1 - y + 0.5f) / size.y * 2.0f - 1.0f,
                        depth(x, y) * 2.0f - 1.0f, 1.0f);
    const glm::vec4 p = f_.geometry.inverseViewProjection * ndc;
    return glm::length(glm::dvec2(p.x, p.z) / static_cast<double>(p.w));
  }

 private:
  float depth(int x, int y) const {
    const glm::ivec2 size = f_.pixels.size;
    return f_.pixels.depth[static_cast<std::size_t>((size.y - 1 - y) * size.x + x)];
  }
  const RenderedFrame& f_;
};

// Sky through a surface: ground within kCrackReach pixels on both sides of the pixel (across or along
// the row), the two no further apart than kCrackSpread of their distance: one surface with sky in it,
// not a gap between a near ridge and a far one.
constexpr int kCrackReach = 3;
constexpr double kCrackSpread = 0.25;
// Where the fog at the far edge (lib/sky.glsl: smoothstep from 0.8 to 1 of it) leaves half a surface
// or more to see.
constexpr double kVisibleEdge = 0.9;

bool crack(const Surfaces& s, int x, int y, int width, int height) {
  for (const glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
    std::optional<double> side[2];
    for (int k = 0; k < 2; ++k) {
      const glm::ivec2 dir = k ? -step : step;
      for (int i = 1; i <= kCrackReach && !side[k]; ++i) {
        const glm::ivec2 p = glm::ivec2(x, y) + dir * i;
        if (p.x < 0 || p.y < 0 || p.x >= width || p.y >= height) break;
        if (!s.sky(p.x, p.y)) side[k] = s.horizontal(p.x, p.y);
      }
    }
    if (side[0] && side[1] && std::abs(*side[0] - *side[1]) <= kCrackSpread * std::max(*side[0], *side[1]))
      return true;
  }
  return false;
}

}  // namespace

LodError measureLodError(const RenderedFrame& lod, const RenderedFrame& truth, double fullDetail,
                         double farEdge, const Image* halfResolution) {
  LodError e;
  const Image& a = lod.image;
  const Image& b = truth.image;
  if (a.width != b.width || a.height != b.height || lod.pixels.size != glm::ivec2(a.width, a.height) ||
      truth.pixels.size != lod.pixels.size)
    return e;
  const Surfaces far(lod), exact(truth);
  std::vector<double> errors, halfErrors;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const bool skyA = far.sky(x, y), skyB = exact.sky(x, y);
      const bool inBand = skyA != skyB || (!skyA && far.horizontal(x, y) > fullDetail) ||
                          (!skyB && exact.horizontal(x, y) > fullDetail);
      // Ground the fog leaves visible in one picture, sky in the other.
      const double visible = kVisibleEdge * farEdge;
      if (skyA && !skyB && exact.horizontal(x, y) < visible) {
        ++e.skyDiffers;
        if (crack(far, x, y, a.width, a.height)) ++e.holes;
      }
      if (skyB && !skyA && far.horizontal(x, y) < visible) ++e.skyDiffers;
      if (!inBand) continue;
      errors.push_back(pixelError(a, b, x, y));
      if (halfResolution) halfErrors.push_back(pixelError(*halfResolution, b, x, y));
    }
  e.band = errors.size();
  const Stats s = statsOf(std::move(errors));
  e.mean = s.mean;
  e.p99 = s.p99;
  if (halfResolution) {
    const Stats h = statsOf(std::move(halfErrors));
    e.halfResolutionMean = h.mean;
    e.halfResolutionP99 = h.p99;
  }
  return e;
}

nlohmann::json lodErrorJson(const LodError& e) {
  nlohmann::json j{{"band_pixels", e.band},
                   {"mean", e.mean},
                   {"p99", e.p99},
                   {"holes", e.holes},
                   {"sky_differs", e.skyDiffers}};
  if (e.halfResolutionMean) {
    j["half_resolution_mean"] = *e.halfResolutionMean;
    j["half_resolution_p99"] = *e.halfResolutionP99;
  }
  return j;
}

}  // namespace terrasol
