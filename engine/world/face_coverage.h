#pragma once
// Which parts of a cell's six sides a block state's shape covers, in 1/16 of a block: what decides
// whether a neighbour's face against it is hidden (a bottom slab hides the lower half of the side it
// touches, nothing of the face above its open top) and, where a side is covered whole, that light
// does not pass through it. Shapes are axis-aligned boxes in 1/16 units. Plain C++.

#include <array>
#include <bitset>
#include <cstdint>
#include <span>

#include "core/model_units.h"
#include "world/coords.h"

namespace terrasol {

// The 1/16 cells of a side, a * kModelUnits + b in its two axes.
using SideMask = std::bitset<kModelUnits * kModelUnits>;

// A box in 1/16 of a block: from <= to on each axis, 0..16.
struct ShapeBox {
  std::array<int, 3> from{0, 0, 0}, to{kModelUnits, kModelUnits, kModelUnits};
  friend bool operator==(const ShapeBox&, const ShapeBox&) = default;
};

// A rectangle on a side, in its two other axes in x, y, z order (west/east: y, z; down/up: x, z;
// north/south: x, y), in 1/16: [a0, a1) x [b0, b1).
struct SideRect {
  int a0 = 0, b0 = 0, a1 = kModelUnits, b1 = kModelUnits;
  friend bool operator==(const SideRect&, const SideRect&) = default;
};

class FaceCoverage {
 public:
  // Nothing covered (air, plants, torches).
  FaceCoverage() = default;
  static FaceCoverage fullCube();
  // The sides the boxes touch, where they touch them.
  static FaceCoverage of(std::span<const ShapeBox> boxes);

  // Covers `rect` on `side` too.
  void add(Direction side, const SideRect& rect);

  // Whether every 1/16 cell of `rect` on `side` is covered.
  bool covers(Direction side, const SideRect& rect) const;
  bool full(Direction side) const { return sides_[static_cast<std::size_t>(side)].all(); }
  bool empty(Direction side) const { return sides_[static_cast<std::size_t>(side)].none(); }
  // The side's 16 x 16 cells, a * 16 + b in its two axes: neighbours' touching sides line up.
  const SideMask& side(Direction side) const { return sides_[static_cast<std::size_t>(side)]; }

 private:
  std::array<SideMask, 6> sides_;
};

// Whether a face on this cell's side `side`, spanning `rect`, is hidden by the neighbour there.
inline bool hiddenBy(const FaceCoverage& neighbour, Direction side, const SideRect& rect) {
  return neighbour.covers(opposite(side), rect);
}

}  // namespace terrasol
