#include "world/terrain_caves.h"

#include <algorithm>
#include <vector>

#include "world/terrain_shape.h"

namespace terrasol {
namespace {

// Floor division for the cave lattice.
constexpr std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

double lerp(double p, double q, double t) {
  return p + (q - p) * t;
}

}  // namespace

TerrainCaves::TerrainCaves(std::uint64_t seed)
    : tunnelA_(seed ^ 0x05), tunnelB_(seed ^ 0x06), caverns_(seed ^ 0x07) {}

double TerrainCaves::lattice(std::int64_t cx, std::int64_t cy, std::int64_t cz) const {
  const double x = static_cast<double>(cx * kCellXZ), y = static_cast<double>(cy * kCellY + kMinY),
               z = static_cast<double>(cz * kCellXZ);
  // Tunnels: where two independent noises are both near zero, a winding tube.
  const double a = tunnelA_.at(x / 80.0, y / 48.0, z / 80.0);
  const double b = tunnelB_.at(x / 80.0, y / 48.0, z / 80.0);
  const double tunnel = a * a + b * b - 0.01;
  // Caverns: large rooms, more common deep down, none near the surface.
  const double depth = smoothstep(40.0, -30.0, y);
  const double cavern = 0.24 - caverns_.fractal(x / 90.0, y / 45.0, z / 90.0, 2) * depth;
  return std::min(tunnel, cavern);
}

double TerrainCaves::density(int x, int y, int z) const {
  const std::int64_t cx = floorDiv(x, kCellXZ), cy = floorDiv(y - kMinY, kCellY), cz = floorDiv(z, kCellXZ);
  const double fx = static_cast<double>(x - cx * kCellXZ) / kCellXZ;
  const double fy = static_cast<double>(y - kMinY - cy * kCellY) / kCellY;
  const double fz = static_cast<double>(z - cz * kCellXZ) / kCellXZ;
  const double c000 = lattice(cx, cy, cz), c100 = lattice(cx + 1, cy, cz);
  const double c010 = lattice(cx, cy + 1, cz), c110 = lattice(cx + 1, cy + 1, cz);
  const double c001 = lattice(cx, cy, cz + 1), c101 = lattice(cx + 1, cy, cz + 1);
  const double c011 = lattice(cx, cy + 1, cz + 1), c111 = lattice(cx + 1, cy + 1, cz + 1);
  return lerp(lerp(lerp(c000, c100, fx), lerp(c010, c110, fx), fy),
              lerp(lerp(c001, c101, fx), lerp(c011, c111, fx), fy), fz);
}

bool TerrainCaves::carveAllowed(int y, int surface) {
  if (y <= kMinY + 4) return false;  // keep the bedrock floor whole
  if (surface <= TerrainShape::kSeaLevel + 1 && y > surface - 6)
    return false;  // no holes in sea or lake beds
  return true;
}

void TerrainCaves::carve(ColumnBlocks& blocks, const ColumnSamples& columns, ChunkPos pos,
                         const TerrainBlocks& b) const {
  const int x0 = pos.minBlockX(), z0 = pos.minBlockZ();
  int maxSurface = kMinY;
  for (const ColumnSample& column : columns) maxSurface = std::max(maxSurface, column.surface);

  // The lattice over this chunk: (n + 1)² x cellsY points, computed once and interpolated per block.
  constexpr int kPoints = kChunkSize / kCellXZ + 1;
  const int cellsY = (maxSurface - kMinY) / kCellY + 2;
  std::vector<double> points(static_cast<std::size_t>(kPoints * kPoints * cellsY));
  auto at = [&](int i, int j, int k) -> double& {
    return points[static_cast<std::size_t>((j * kPoints + k) * kPoints + i)];
  };
  for (int j = 0; j < cellsY; ++j)
    for (int k = 0; k < kPoints; ++k)
      for (int i = 0; i < kPoints; ++i) at(i, j, k) = lattice(x0 / kCellXZ + i, j, z0 / kCellXZ + k);

  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      const int h = columns[static_cast<std::size_t>(columnIndex(x, z))].surface;
      const int cx = x / kCellXZ, cz = z / kCellXZ;
      const double fx = static_cast<double>(x % kCellXZ) / kCellXZ;
      const double fz = static_cast<double>(z % kCellXZ) / kCellXZ;
      for (int y = kMinY; y <= h; ++y) {
        if (!carveAllowed(y, h)) continue;
        const int cy = (y - kMinY) / kCellY;
        const double fy = static_cast<double>((y - kMinY) % kCellY) / kCellY;
        // Same arithmetic, in the same order, as density(), so both agree bit for bit.
        const double d = lerp(lerp(lerp(at(cx, cy, cz), at(cx + 1, cy, cz), fx),
                                   lerp(at(cx, cy + 1, cz), at(cx + 1, cy + 1, cz), fx), fy),
                              lerp(lerp(at(cx, cy, cz + 1), at(cx + 1, cy, cz + 1), fx),
                                   lerp(at(cx, cy + 1, cz + 1), at(cx + 1, cy + 1, cz + 1), fx), fy),
                              fz);
        if (d < 0.0) blocks.at(x, y, z) = y <= kLavaLevel ? b.lava : kAir;
      }
    }
}

}  // namespace terrasol
