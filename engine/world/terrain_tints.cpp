// The terrain generator's tints: each column's grass and foliage colour, blended across biome borders.
#include <array>
#include <cmath>

#include "world/terrain_stages.h"

namespace terrasol {

void blendTints(Chunk& chunk, const TerrainContext& terrain) {
  // Biomes are sampled on a lattice every kStep blocks (Minecraft's biome cells are 4 blocks too),
  // each node averaged over its (2 kRadius + 1)² neighbours, and columns interpolated bilinearly
  // between nodes: a border fades over about 20 columns, and chunks agree along their edges because
  // the nodes lie on one world-wide lattice.
  constexpr int kStep = 4, kRadius = 2, kNodes = kChunkSize / kStep + 1, kSamples = kNodes + 2 * kRadius;
  const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
  struct Tint {
    float temperature = 0, downfall = 0;
  };
  std::array<Tint, kSamples * kSamples> samples;
  for (int j = 0; j < kSamples; ++j)
    for (int i = 0; i < kSamples; ++i) {
      const int x = x0 + (i - kRadius) * kStep, z = z0 + (j - kRadius) * kStep;
      const TintClimate t = biomeTint(terrain.biomeAt(x, z));
      samples[static_cast<std::size_t>(j * kSamples + i)] = {static_cast<float>(t.temperature),
                                                             static_cast<float>(t.downfall)};
    }
  std::array<Tint, kNodes * kNodes> nodes;
  constexpr float kArea = (2 * kRadius + 1) * (2 * kRadius + 1);
  for (int j = 0; j < kNodes; ++j)
    for (int i = 0; i < kNodes; ++i) {
      Tint sum;
      for (int dj = 0; dj <= 2 * kRadius; ++dj)
        for (int di = 0; di <= 2 * kRadius; ++di) {
          const Tint& s = samples[static_cast<std::size_t>((j + dj) * kSamples + i + di)];
          sum.temperature += s.temperature;
          sum.downfall += s.downfall;
        }
      nodes[static_cast<std::size_t>(j * kNodes + i)] = {sum.temperature / kArea, sum.downfall / kArea};
    }
  auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(v)); };
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) {
      const int i = x / kStep, j = z / kStep;
      const float fx = static_cast<float>(x % kStep) / kStep, fz = static_cast<float>(z % kStep) / kStep;
      auto node = [&](int di, int dj) { return nodes[static_cast<std::size_t>((j + dj) * kNodes + i + di)]; };
      auto mix = [&](float Tint::*axis) {
        const float north = node(0, 0).*axis + (node(1, 0).*axis - node(0, 0).*axis) * fx;
        const float south = node(0, 1).*axis + (node(1, 1).*axis - node(0, 1).*axis) * fx;
        return north + (south - north) * fz;
      };
      chunk.setTint(x, z, climateOnly({byte(mix(&Tint::temperature)), byte(mix(&Tint::downfall))}));
    }
}

}  // namespace terrasol
