#include "support/reference_light.h"

#include <algorithm>
#include <climits>
#include <sstream>

namespace terrasol::testing {

ReferenceLight::ReferenceLight(const World& world) {
  int minX = INT_MAX, minZ = INT_MAX, maxX = INT_MIN, maxZ = INT_MIN;
  world.forEachChunk([&](const Chunk& c) {
    minX = std::min(minX, c.pos().x), maxX = std::max(maxX, c.pos().x);
    minZ = std::min(minZ, c.pos().z), maxZ = std::max(maxZ, c.pos().z);
  });
  if (minX > maxX) return;
  x0_ = minX * 16, z0_ = minZ * 16;
  width_ = static_cast<std::size_t>(maxX - minX + 1) * 16,
  depth_ = static_cast<std::size_t>(maxZ - minZ + 1) * 16;
  const std::size_t cells = width_ * depth_ * static_cast<std::size_t>(kMaxY - kMinY);
  opacity_.assign(cells, 255);
  sides_.assign(cells, 0);
  state_.assign(cells, kAir);
  shapes_ = world.shapes();
  block_.assign(cells, 0);
  sky_.assign(cells, 0);
  const BlockRegistry& blocks = world.blocks();
  world.forEachChunk([&](const Chunk& c) {
    for (int y = kMinY; y < kMaxY; ++y)
      for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) {
          const BlockPos p{c.pos().minBlockX() + x, y, c.pos().minBlockZ() + z};
          const BlockId state = c.get(x, y, z);
          opacity_[index(p)] = blocks.opacities()[state];
          sides_[index(p)] = world.shapes() ? world.shapes()->lightSides()[c.get(x, y, z)] : 0;
          state_[index(p)] = c.get(x, y, z);
          block_[index(p)] = blocks.emissions()[state];
        }
    // Sky: 15 straight down into every cell light enters from above (no opacity, top open); a cell
    // whose bottom is closed (a snow layer) is lit so and stops it. The top layer, when light cannot
    // enter it so, is lit through its own opacity.
    constexpr std::uint8_t kDownSide = 0b0100, kUpSide = 0b1000;
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x) {
        const int wx = c.pos().minBlockX() + x, wz = c.pos().minBlockZ() + z;
        for (int y = kMaxY - 1; y >= kMinY; --y) {
          const std::size_t i = index({wx, y, wz});
          if (opacity_[i] != 0 || (sides_[i] & kUpSide)) {
            if (y == kMaxY - 1) sky_[i] = static_cast<std::uint8_t>(15 - std::max<int>(1, opacity_[i]));
            break;
          }
          sky_[i] = 15;
          if (sides_[i] & kDownSide) break;
        }
      }
  });
  spread(block_);
  spread(sky_);
}

void ReferenceLight::spread(std::vector<std::uint8_t>& light) const {
  std::vector<std::size_t> buckets[16];
  for (std::size_t i = 0; i < light.size(); ++i) {
    if (light[i] > 1) buckets[light[i]].push_back(i);
  }
  const std::size_t layer = width_ * depth_;
  for (int level = 15; level > 1; --level) {
    for (std::size_t k = 0; k < buckets[level].size(); ++k) {
      const std::size_t i = buckets[level][k];
      if (light[i] != level) continue;
      const std::size_t x = i % width_, z = (i / width_) % depth_, y = i / layer;
      const std::size_t neighbours[6] = {
          x > 0 ? i - 1 : SIZE_MAX,
          x + 1 < width_ ? i + 1 : SIZE_MAX,
          y > 0 ? i - layer : SIZE_MAX,
          y + 1 < static_cast<std::size_t>(kMaxY - kMinY) ? i + layer : SIZE_MAX,
          z > 0 ? i - width_ : SIZE_MAX,
          z + 1 < depth_ ? i + width_ : SIZE_MAX,
      };
      for (int d = 0; d < 6; ++d) {
        const std::size_t n = neighbours[d];
        if (n == SIZE_MAX || opacity_[n] == 255) continue;
        // Not across a side the two cells' shapes cover together (side d of this one, d ^ 1 of n).
        if (closed(i, n, d)) continue;
        const int offer = level - std::max<int>(1, opacity_[n]);
        if (offer > light[n]) {
          light[n] = static_cast<std::uint8_t>(offer);
          buckets[offer].push_back(n);
        }
      }
    }
  }
}

bool ReferenceLight::closed(std::size_t i, std::size_t n, int d) const {
  if (!shapes_) return false;
  const auto& masks = shapes_->lightFaceMasks();
  const auto& a = shapes_->lightFaces()[state_[i]];
  const auto& b = shapes_->lightFaces()[state_[n]];
  return (masks[a[static_cast<std::size_t>(d)]] | masks[b[static_cast<std::size_t>(d ^ 1)]]).all();
}

std::string compareWithReference(const World& world) {
  const ReferenceLight reference(world);
  std::ostringstream report;
  int mismatches = 0;
  world.forEachChunk([&](const Chunk& c) {
    const ChunkLight& light = c.light();
    for (int s = 0; s < kSectionCount; ++s)
      for (int i = 0; i < Section::kVolume; ++i) {
        const BlockPos p{c.pos().minBlockX() + (i & 15), kMinY + s * 16 + (i >> 8),
                         c.pos().minBlockZ() + ((i >> 4) & 15)};
        const int block = light.block[static_cast<std::size_t>(s)].get(i),
                  sky = light.sky[static_cast<std::size_t>(s)].get(i);
        if (block == reference.block(p) && sky == reference.sky(p)) continue;
        if (++mismatches <= 5) {
          report << "(" << p.x << ", " << p.y << ", " << p.z << "): block " << block << " expected "
                 << int{reference.block(p)} << ", sky " << sky << " expected " << int{reference.sky(p)}
                 << "\n";
        }
      }
  });
  if (mismatches > 5) report << "... " << mismatches << " cells differ in all\n";
  return report.str();
}

}  // namespace terrasol::testing
