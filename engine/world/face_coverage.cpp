#include "world/face_coverage.h"

#include <algorithm>

namespace terrasol {
namespace {

// The side's two axes (x, y, z order) and the axis across it.
struct SideAxes {
  int a, b, across;
  bool atMax;  // the side lies at 16 on `across` (east, up, south), else at 0
};

constexpr SideAxes axesOf(Direction side) {
  switch (side) {
    case Direction::West:
      return {1, 2, 0, false};
    case Direction::East:
      return {1, 2, 0, true};
    case Direction::Down:
      return {0, 2, 1, false};
    case Direction::Up:
      return {0, 2, 1, true};
    case Direction::North:
      return {0, 1, 2, false};
    case Direction::South:
      return {0, 1, 2, true};
  }
  return {0, 1, 2, false};
}

}  // namespace

FaceCoverage FaceCoverage::fullCube() {
  FaceCoverage c;
  for (auto& side : c.sides_) side.set();
  return c;
}

FaceCoverage FaceCoverage::of(std::span<const ShapeBox> boxes) {
  FaceCoverage c;
  for (const ShapeBox& box : boxes) {
    for (int d = 0; d < 6; ++d) {
      const SideAxes s = axesOf(static_cast<Direction>(d));
      const auto at = [](const std::array<int, 3>& v, int axis) { return v[static_cast<std::size_t>(axis)]; };
      const bool touches = s.atMax ? at(box.to, s.across) >= kModelUnits : at(box.from, s.across) <= 0;
      if (!touches) continue;
      c.add(static_cast<Direction>(d),
            {at(box.from, s.a), at(box.from, s.b), at(box.to, s.a), at(box.to, s.b)});
    }
  }
  return c;
}

void FaceCoverage::add(Direction side, const SideRect& rect) {
  auto& bits = sides_[static_cast<std::size_t>(side)];
  for (int a = std::max(rect.a0, 0); a < std::min(rect.a1, kModelUnits); ++a)
    for (int b = std::max(rect.b0, 0); b < std::min(rect.b1, kModelUnits); ++b)
      bits.set(static_cast<std::size_t>(a * kModelUnits + b));
}

bool FaceCoverage::covers(Direction side, const SideRect& rect) const {
  const auto& bits = sides_[static_cast<std::size_t>(side)];
  if (bits.all()) return true;
  for (int a = std::max(rect.a0, 0); a < std::min(rect.a1, kModelUnits); ++a)
    for (int b = std::max(rect.b0, 0); b < std::min(rect.b1, kModelUnits); ++b) {
      if (!bits.test(static_cast<std::size_t>(a * kModelUnits + b))) return false;
    }
  return true;
}

}  // namespace terrasol
