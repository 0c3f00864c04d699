#pragma once
// Minecraft's cloud layer: a pack's textures/environment/clouds.png laid over the world, one texel per
// 12 x 12 blocks, repeating, at height 192, drifting 0.03 blocks a tick towards -x (west). Flat clouds
// are the texels on a plane; fancy clouds are 4-block-high boxes. Where it lies is a function of the
// world tick alone, so the same tick gives the same sky. Plain C++: the shaders (lib/clouds.glsl) get
// these numbers injected, and the tests check the GPU's layer against cloudCovers().

#include <cmath>
#include <cstdint>
#include <vector>

namespace terrasol {

inline constexpr double kCloudBottom = 192.0;   // blocks
inline constexpr double kCloudThickness = 4.0;  // fancy clouds' boxes
// Volumetric clouds: the slab their density fills (from the same bottom), how much light a block of
// the densest cloud lets through (exp(-extinction)), and the steps a view ray and a ray towards the
// light take through them.
inline constexpr double kCloudVolumeThickness = 24.0;
inline constexpr float kCloudExtinction = 0.35f;  // per block at full density
inline constexpr int kCloudVolumeSteps = 16, kCloudLightSteps = 3;
inline constexpr double kCloudVolumeSpan = 96.0;  // blocks of a ray marched at most
inline constexpr double kCloudCellBlocks = 12.0;  // one texel's side
// Drift per tick as a fraction 3/100, so a whole cycle over the map is an exact number of ticks.
inline constexpr std::int64_t kCloudDriftNumerator = 3, kCloudDriftDenominator = 100;
inline constexpr float kCloudAlpha = 0.8f;   // vanilla's clouds are this opaque
inline constexpr float kCloudAlbedo = 0.9f;  // of the light that reaches a cloud's face
// How much of the sun a fully covered column loses to the cloud above it.
inline constexpr float kCloudShadow = 0.6f;
// Blocks (horizontally) at which clouds have faded out: beyond the world's fog, as vanilla's are.
inline constexpr float kCloudRange = 384.0f;

// The layer's coverage: 0 = clear, 255 = cloud (clouds.png's alpha), row-major, z down the rows.
struct CloudMap {
  int width = 0, height = 0;
  std::vector<std::uint8_t> cover;

  bool empty() const { return width <= 0 || height <= 0; }
  std::uint8_t at(std::int64_t column, std::int64_t row) const {
    const auto wrap = [](std::int64_t v, int n) { return static_cast<int>(((v % n) + n) % n); };
    return cover[static_cast<std::size_t>(wrap(row, height)) * static_cast<std::size_t>(width) +
                 static_cast<std::size_t>(wrap(column, width))];
  }
};

// Blocks the layer has moved towards -x at `ticks`, wrapped to [0, the map's width in blocks): exact for
// any tick, negative ones too.
inline double cloudDrift(std::int64_t ticks, int mapWidth) {
  const std::int64_t cycle = static_cast<std::int64_t>(mapWidth) *
                             static_cast<std::int64_t>(kCloudCellBlocks) * kCloudDriftDenominator /
                             kCloudDriftNumerator;  // ticks per whole cycle
  const std::int64_t t = ((ticks % cycle) + cycle) % cycle;
  return static_cast<double>(t * kCloudDriftNumerator) / static_cast<double>(kCloudDriftDenominator);
}

// Whether the column of world (x, z) lies under a cloud texel at `ticks`.
inline bool cloudCovers(const CloudMap& map, double x, double z, std::int64_t ticks) {
  if (map.empty()) return false;
  const double u = (x + cloudDrift(ticks, map.width)) / kCloudCellBlocks;
  const double v = z / kCloudCellBlocks;
  return map.at(static_cast<std::int64_t>(std::floor(u)), static_cast<std::int64_t>(std::floor(v))) >= 128;
}

}  // namespace terrasol
