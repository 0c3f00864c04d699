#include "world/chunk.h"

namespace terrasol {

int Chunk::highestBlock(int x, int z) const {
  for (int s = kSectionCount - 1; s >= 0; --s) {
    const Section& section = sections_[static_cast<std::size_t>(s)];
    if (section.isAllAir()) continue;
    for (int ly = kLastCell; ly >= 0; --ly)
      if (section.get(x, ly, z) != kAir) return sectionMinY(s) + ly;
  }
  return kMinY - 1;
}

std::size_t Chunk::compact() {
  for (auto& s : sections_) s.compact();
  return memoryBytes();
}

std::size_t Chunk::memoryBytes() const {
  std::size_t bytes = sizeof(Chunk);
  for (const auto& s : sections_) bytes += s.memoryBytes();
  bytes += light_.memoryBytes();
  return bytes;
}

}  // namespace terrasol
