#include "world/chunk.h"

namespace terrasol {

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
