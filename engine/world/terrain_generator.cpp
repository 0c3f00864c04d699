#include "world/terrain_generator.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace terrasol {
namespace {

double smoothstep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Index into a chunk-sized column buffer laid out exactly like 24 consecutive sections.
constexpr std::size_t columnIndex(int x, int y, int z) {
  return static_cast<std::size_t>(y - kMinY) * 256 + static_cast<std::size_t>(z) * 16 +
         static_cast<std::size_t>(x);
}
static_assert(columnIndex(3, kMinY + 17, 5) == 4096 + Section::index(3, 1, 5));

// Floor division for the cave lattice.
constexpr std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

}  // namespace

TerrainGenerator::TerrainGenerator(std::uint64_t seed, const BlockRegistry& r)
    : seed_(seed),
      b_{r.id("stone"),
         r.id("dirt"),
         r.id("grass_block"),
         r.id("sand"),
         r.id("gravel"),
         r.id("bedrock"),
         r.id("water"),
         r.id("lava"),
         r.id("snow"),
         r.id("oak_log"),
         r.id("oak_leaves"),
         r.id("short_grass"),
         r.id("dandelion"),
         r.id("poppy"),
         r.id("coal_ore"),
         r.id("iron_ore"),
         r.id("gold_ore"),
         r.id("glowstone"),
         r.id("deepslate"),
         r.id("deepslate_coal_ore"),
         r.id("deepslate_iron_ore"),
         r.id("deepslate_gold_ore"),
         r.id("copper_ore"),
         r.id("deepslate_copper_ore"),
         r.id("lapis_ore"),
         r.id("deepslate_lapis_ore"),
         r.id("diamond_ore"),
         r.id("deepslate_diamond_ore"),
         r.id("emerald_ore"),
         r.id("sandstone"),
         r.id("ice"),
         r.id("snow_layer"),
         r.id("birch_log"),
         r.id("birch_leaves"),
         r.id("spruce_log"),
         r.id("spruce_leaves"),
         r.id("acacia_log"),
         r.id("acacia_leaves"),
         r.id("cactus"),
         r.id("dead_bush"),
         r.id("fern")},
      biomes_(seed),
      continents_(seed ^ 0x01),
      hills_(seed ^ 0x02),
      mountains_(seed ^ 0x03),
      ridges_(seed ^ 0x04),
      tunnelA_(seed ^ 0x05),
      tunnelB_(seed ^ 0x06),
      caverns_(seed ^ 0x07),
      forests_(seed ^ 0x08) {}

int TerrainGenerator::surfaceHeight(int x, int z) const {
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

double TerrainGenerator::caveLattice(std::int64_t cx, std::int64_t cy, std::int64_t cz) const {
  const double x = static_cast<double>(cx * kCaveCellXZ), y = static_cast<double>(cy * kCaveCellY + kMinY),
               z = static_cast<double>(cz * kCaveCellXZ);
  // Tunnels: where two independent noises are both near zero, a winding tube.
  const double a = tunnelA_.at(x / 80.0, y / 48.0, z / 80.0);
  const double b = tunnelB_.at(x / 80.0, y / 48.0, z / 80.0);
  const double tunnel = a * a + b * b - 0.01;
  // Caverns: large rooms, more common deep down, none near the surface.
  const double depth = smoothstep(40.0, -30.0, y);
  const double cavern = 0.24 - caverns_.fractal(x / 90.0, y / 45.0, z / 90.0, 2) * depth;
  return std::min(tunnel, cavern);
}

double TerrainGenerator::caveDensity(int x, int y, int z) const {
  const std::int64_t cx = floorDiv(x, kCaveCellXZ), cy = floorDiv(y - kMinY, kCaveCellY),
                     cz = floorDiv(z, kCaveCellXZ);
  const double fx = static_cast<double>(x - cx * kCaveCellXZ) / kCaveCellXZ;
  const double fy = static_cast<double>(y - kMinY - cy * kCaveCellY) / kCaveCellY;
  const double fz = static_cast<double>(z - cz * kCaveCellXZ) / kCaveCellXZ;
  auto lerp = [](double p, double q, double t) { return p + (q - p) * t; };
  const double c000 = caveLattice(cx, cy, cz), c100 = caveLattice(cx + 1, cy, cz);
  const double c010 = caveLattice(cx, cy + 1, cz), c110 = caveLattice(cx + 1, cy + 1, cz);
  const double c001 = caveLattice(cx, cy, cz + 1), c101 = caveLattice(cx + 1, cy, cz + 1);
  const double c011 = caveLattice(cx, cy + 1, cz + 1), c111 = caveLattice(cx + 1, cy + 1, cz + 1);
  return lerp(lerp(lerp(c000, c100, fx), lerp(c010, c110, fx), fy),
              lerp(lerp(c001, c101, fx), lerp(c011, c111, fx), fy), fz);
}

bool TerrainGenerator::carveAllowed(int y, int surface) const {
  if (y <= kMinY + 4) return false;                               // keep the bedrock floor whole
  if (surface <= kSeaLevel + 1 && y > surface - 6) return false;  // no holes in sea or lake beds
  return true;
}

void TerrainGenerator::generate(Chunk& chunk) const {
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  std::vector<BlockId> column(static_cast<std::size_t>(kSectionCount) * Section::kVolume, kAir);
  std::array<int, 256> surface{};
  int maxSurface = kMinY;
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) {
      const int h = surfaceHeight(x0 + x, z0 + z);
      surface[static_cast<std::size_t>(z * 16 + x)] = h;
      maxSurface = std::max(maxSurface, h);
    }

  // Cave lattice for this chunk: 5 x n x 5 points, computed once and interpolated per block.
  const int cellsY = (maxSurface - kMinY) / kCaveCellY + 2;
  std::vector<double> lattice(static_cast<std::size_t>(5 * 5 * cellsY));
  auto latticeAt = [&](int i, int j, int k) -> double& {
    return lattice[static_cast<std::size_t>((j * 5 + k) * 5 + i)];
  };
  for (int j = 0; j < cellsY; ++j)
    for (int k = 0; k < 5; ++k)
      for (int i = 0; i < 5; ++i)
        latticeAt(i, j, k) = caveLattice(x0 / kCaveCellXZ + i, j, z0 / kCaveCellXZ + k);

  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) {
      const int h = surface[static_cast<std::size_t>(z * 16 + x)];
      const bool beach = h >= kSeaLevel - 3 && h <= kSeaLevel + 1;
      const bool underwater = h < kSeaLevel - 3;
      const bool peak = h >= 150;
      const bool rocky = h >= 118;
      const Biome biome = biomes_.biomeAt(x0 + x, z0 + z, h);
      const bool desert = biome == Biome::Desert, snowy = biome == Biome::SnowyPlains;
      const std::uint64_t r = hashCoords(seed_, x0 + x, 1, z0 + z);
      const int depthOfDirt = 3 + static_cast<int>(r % 2);
      const int bedrockTop = kMinY + 1 + static_cast<int>((r >> 8) % 4);
      for (int y = kMinY; y <= h; ++y) {
        // Deepslate below y = 0, thinning out to none at kDeepslateTop.
        const bool deep =
            y < 0 || (y < kDeepslateTop &&
                      static_cast<int>(hashCoords(seed_ ^ 0x0D, x0 + x, y, z0 + z) % kDeepslateTop) >= y);
        BlockId id = deep ? b_.deepslate : b_.stone;
        if (y <= bedrockTop && (y == kMinY || ((r >> (16 + y - kMinY)) & 1))) {
          id = b_.bedrock;
        } else if (y == h) {
          id = peak              ? b_.snow
               : rocky           ? b_.stone
               : underwater      ? ((r >> 40) % 4 == 0 ? b_.gravel : b_.sand)
               : beach || desert ? b_.sand
                                 : b_.grass;
        } else if (y > h - depthOfDirt && !rocky) {
          id = (beach || underwater || desert) ? b_.sand : b_.dirt;
        } else if (desert && y > h - depthOfDirt - 4) {
          id = b_.sandstone;  // sand lies on sandstone
        }
        column[columnIndex(x, y, z)] = id;
      }
      for (int y = h + 1; y <= kSeaLevel; ++y) column[columnIndex(x, y, z)] = b_.water;
      // Snowy plains: ice on still water.
      if (snowy && h < kSeaLevel) column[columnIndex(x, kSeaLevel, z)] = b_.ice;

      // Carve caves through the solid part of the column.
      const int cx = x / kCaveCellXZ, cz = z / kCaveCellXZ;
      const double fx = static_cast<double>(x % kCaveCellXZ) / kCaveCellXZ;
      const double fz = static_cast<double>(z % kCaveCellXZ) / kCaveCellXZ;
      for (int y = kMinY; y <= h; ++y) {
        if (!carveAllowed(y, h)) continue;
        const int cy = (y - kMinY) / kCaveCellY;
        const double fy = static_cast<double>((y - kMinY) % kCaveCellY) / kCaveCellY;
        auto lerp = [](double p, double q, double t) { return p + (q - p) * t; };
        // Same arithmetic, in the same order, as caveDensity(), so both agree bit for bit.
        const double d =
            lerp(lerp(lerp(latticeAt(cx, cy, cz), latticeAt(cx + 1, cy, cz), fx),
                      lerp(latticeAt(cx, cy + 1, cz), latticeAt(cx + 1, cy + 1, cz), fx), fy),
                 lerp(lerp(latticeAt(cx, cy, cz + 1), latticeAt(cx + 1, cy, cz + 1), fx),
                      lerp(latticeAt(cx, cy + 1, cz + 1), latticeAt(cx + 1, cy + 1, cz + 1), fx), fy),
                 fz);
        if (d < 0.0) column[columnIndex(x, y, z)] = y <= kLavaLevel ? b_.lava : kAir;
      }
      // And a layer of snow on the ground, where caves left it.
      if (snowy && h >= kSeaLevel && !rocky && column[columnIndex(x, h, z)] != kAir) {
        column[columnIndex(x, h + 1, z)] = b_.snowLayer;
      }
    }

  for (int s = 0; s < kSectionCount; ++s) {
    Section& section = chunk.section(s);
    std::copy_n(column.begin() + static_cast<std::ptrdiff_t>(s) * Section::kVolume, Section::kVolume,
                section.mutableBlocks().begin());
    section.compact();
  }
  placeOres(chunk);
  placeGlowstone(chunk);
  placeTrees(chunk);
  placePlants(chunk);
  fillTints(chunk);
  chunk.compact();
}

}  // namespace terrasol
