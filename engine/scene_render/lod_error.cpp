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

// Sky through a surface: ground of one surface (no further apart than kCrackSpread of its distance)
// within kCrackReach pixels above and below the pixel, or left and right with ground above it too.
// A notch in a skyline (sky above, between two crowns) is not a hole: a silhouette drawn differently.
constexpr int kCrackReach = 3;
constexpr double kCrackSpread = 0.25;
// Where the fog at the far edge (lib/sky.glsl: smoothstep from 0.8 to 1 of it) leaves half a surface
// or more to see.
constexpr double kVisibleEdge = 0.9;

// The distance of the nearest ground within kCrackReach pixels from (x, y) along `dir`.
std::optional<double> groundAlong(const Surfaces& s, glm::ivec2 at, glm::ivec2 dir, glm::ivec2 size) {
  for (int i = 1; i <= kCrackReach; ++i) {
    const glm::ivec2 p = at + dir * i;
    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) return std::nullopt;
    if (!s.sky(p.x, p.y)) return s.horizontal(p.x, p.y);
  }
  return std::nullopt;
}

bool oneSurface(std::optional<double> a, std::optional<double> b) {
  return a && b && std::abs(*a - *b) <= kCrackSpread * std::max(*a, *b);
}

bool crack(const Surfaces& s, int x, int y, int width, int height) {
  const glm::ivec2 at(x, y), size(width, height);
  const std::optional<double> above = groundAlong(s, at, {0, -1}, size);
  if (oneSurface(above, groundAlong(s, at, {0, 1}, size))) return true;
  return above && oneSurface(groundAlong(s, at, {-1, 0}, size), groundAlong(s, at, {1, 0}, size));
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
