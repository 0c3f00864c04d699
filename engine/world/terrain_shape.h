#pragma once
// The land's shape: the height of every column's surface, from 2D noise (continents, hills, ridged
// mountains). Pure and deterministic per seed.

#include <algorithm>
#include <cstdint>

#include "world/noise.h"

namespace terrasol {

// Hermite interpolation of x between a and b: 0 at or before a, 1 at or after b.
inline double smoothstep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

class TerrainShape {
 public:
  static constexpr int kSeaLevel = 62;        // highest water block
  static constexpr int kRockyFrom = 118;      // surfaces this high are bare stone
  static constexpr int kSnowyPeakFrom = 150;  // and this high snow-covered

  explicit TerrainShape(std::uint64_t seed);

  int surfaceHeight(int x, int z) const;

 private:
  Noise continents_, hills_, mountains_, ridges_;
};

}  // namespace terrasol
