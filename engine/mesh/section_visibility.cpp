#include "mesh/section_visibility.h"

#include <array>
#include <bitset>

namespace terrasol {

FaceLinks sectionFaceLinks(const SectionSnapshot& snapshot) {
  constexpr int kCells = 16 * 16 * 16;
  const auto open = [&](int i) { return !snapshot.opaque[static_cast<std::size_t>(
                                     SectionSnapshot::index(i & 15, i >> 8, (i >> 4) & 15))]; };
  std::bitset<kCells> seen;
  std::array<std::uint16_t, kCells> stack;
  FaceLinks links = kNoFacesLinked;
  for (int start = 0; start < kCells; ++start) {
    if (seen[static_cast<std::size_t>(start)] || !open(start)) continue;
    // One open region: the faces it touches are all linked to each other.
    unsigned faces = 0;
    int top = 0;
    stack[static_cast<std::size_t>(top++)] = static_cast<std::uint16_t>(start);
    seen.set(static_cast<std::size_t>(start));
    while (top > 0) {
      const int i = stack[static_cast<std::size_t>(--top)];
      const int x = i & 15, z = (i >> 4) & 15, y = i >> 8;
      faces |= (x == 0 ? 1u : 0u) | (x == 15 ? 2u : 0u) | (y == 0 ? 4u : 0u) | (y == 15 ? 8u : 0u) |
               (z == 0 ? 16u : 0u) | (z == 15 ? 32u : 0u);
      const auto visit = [&](bool inside, int j) {
        if (inside && !seen[static_cast<std::size_t>(j)] && open(j)) {
          seen.set(static_cast<std::size_t>(j));
          stack[static_cast<std::size_t>(top++)] = static_cast<std::uint16_t>(j);
        }
      };
      visit(x > 0, i - 1);
      visit(x < 15, i + 1);
      visit(z > 0, i - 16);
      visit(z < 15, i + 16);
      visit(y > 0, i - 256);
      visit(y < 15, i + 256);
    }
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if ((faces >> a & 1u) && (faces >> b & 1u)) links |= FaceLinks{1} << (a * 6 + b);
    if (links == kAllFacesLinked) break;
  }
  return links;
}

}  // namespace terrasol
