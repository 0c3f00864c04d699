#include "world/terrain_shape.h"

#include <cmath>

#include "world/coords.h"

namespace terrasol {

TerrainShape::TerrainShape(std::uint64_t seed)
    : continents_(seed ^ 0x01), hills_(seed ^ 0x02), mountains_(seed ^ 0x03), ridges_(seed ^ 0x04) {}

int TerrainShape::surfaceHeight(int x, int z) const {
  // Fractal noise stays within about +-0.5; the factors of 2 bring it to about +-1.
  const double c = continents_.fractal(x / 700.0, z / 700.0, 4) * 2.0 + 0.2;  // biased towards land
  const double h = hills_.fractal(x / 160.0, z / 160.0, 4) * 2.0;
  const double m = smoothstep(0.0, 0.35, mountains_.fractal(x / 450.0, z / 450.0, 3) * 2.0);
  const double ridge = 1.0 - std::abs(ridges_.fractal(x / 140.0, z / 140.0, 4) * 2.0);
  const double land = smoothstep(-0.35, 0.1, c);  // 0 in deep ocean, 1 inland
  double height = 48.0 + 22.0 * land + 10.0 * c;  // ocean floor ~40, plains ~66..74
  height += h * (3.0 + 14.0 * land);              // gentle plains, rolling hills inland
  height += land * m * (30.0 + 100.0 * ridge * ridge);
  return std::clamp(static_cast<int>(std::floor(height)), kMinY + 8, kMaxY - 40);
}

}  // namespace terrasol
