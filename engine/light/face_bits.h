#pragma once
// Masks of a section's faces, bit d for Direction d (world/coords.h: west, east, down, up, north,
// south): the directions an entry still spreads in, the neighbours a cell has in its own section,
// the faces a written cell lies on. Internal to engine/light.

#include <cstdint>

#include "world/coords.h"

namespace terrasol::light {

constexpr unsigned faceBit(Direction d) {
  return 1u << static_cast<unsigned>(d);
}
constexpr unsigned faceBit(int direction) {  // a Direction's number
  return 1u << direction;
}
inline constexpr unsigned kWestFace = faceBit(Direction::West);
inline constexpr unsigned kEastFace = faceBit(Direction::East);
inline constexpr unsigned kDownFace = faceBit(Direction::Down);
inline constexpr unsigned kUpFace = faceBit(Direction::Up);
inline constexpr unsigned kNorthFace = faceBit(Direction::North);
inline constexpr unsigned kSouthFace = faceBit(Direction::South);
inline constexpr std::uint8_t kAllFaces = 0x3F;
static_assert(kAllFaces == (kWestFace | kEastFace | kDownFace | kUpFace | kNorthFace | kSouthFace));

// 1 when `mask` has Direction d's bit, else 0.
constexpr int hasFace(unsigned mask, Direction d) {
  return static_cast<int>(mask >> static_cast<unsigned>(d) & 1u);
}

// The faces of the section that its cell (x, y, z) lies on.
constexpr unsigned sectionFaces(int x, int y, int z) {
  return (x == 0) * kWestFace | (x == kLastCell) * kEastFace | (y == 0) * kDownFace |
         (y == kLastCell) * kUpFace | (z == 0) * kNorthFace | (z == kLastCell) * kSouthFace;
}
static_assert(sectionFaces(0, 5, kLastCell) == (kWestFace | kSouthFace) && sectionFaces(1, 2, 3) == 0);

}  // namespace terrasol::light
