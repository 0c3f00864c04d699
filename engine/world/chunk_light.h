#pragma once
// A chunk's light, filled in and kept up to date by engine/light: block light and sky light per
// section, and the sky heightmap. Plain data; world code only stores it.

#include <array>
#include <cstdint>

#include "world/coords.h"
#include "world/nibble_array.h"

namespace terrasol {

struct ChunkLight {
  std::array<NibbleArray, kSectionCount> block;
  std::array<NibbleArray, kSectionCount> sky;
  // Per column (columnIndex): y of the highest cell the sky's light does not reach straight down: a
  // block with light opacity >= 1 or a light side up, or the cell under one with only a light side
  // down (light/sky_columns.h), or kMinY - 1. Every cell above it has sky light 15.
  std::array<std::int16_t, kChunkArea> skyTop{};
  // Light-emitting blocks per section, so sections without any skip the search for sources.
  std::array<std::uint16_t, kSectionCount> emitters{};
  // Cells whose block has light sides (BlockShapes::lightSides) per section: where the flood fill
  // must look at the cell it spreads from.
  std::array<std::uint16_t, kSectionCount> shaped{};
  bool lit = false;  // set once the light engine has lit the chunk

  std::size_t memoryBytes() const {
    std::size_t bytes = 0;
    for (int s = 0; s < kSectionCount; ++s) bytes += block[s].memoryBytes() + sky[s].memoryBytes();
    return bytes;
  }
};

}  // namespace terrasol
