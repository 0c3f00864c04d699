#include "mesh/section_visibility.h"

#include <array>
#include <bitset>

namespace terrasol {

FaceLinks sectionFaceLinks(const SectionSnapshot& snapshot) {
  constexpr int kCells = Section::kVolume;  // by Section::index
  const auto open = [&](int i) {
    return !snapshot.opaque[static_cast<std::size_t>(
        SectionSnapshot::index(Section::xOf(i), Section::yOf(i), Section::zOf(i)))];
  };
  // Bit d of `faces` for Direction d.
  const auto on = [](bool onFace, Direction d) { return onFace ? 1u << static_cast<int>(d) : 0u; };
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
      const int x = Section::xOf(i), z = Section::zOf(i), y = Section::yOf(i);
      faces |= on(x == 0, Direction::West) | on(x == kLastCell, Direction::East) |
               on(y == 0, Direction::Down) | on(y == kLastCell, Direction::Up) |
               on(z == 0, Direction::North) | on(z == kLastCell, Direction::South);
      const auto visit = [&](bool inside, int j) {
        if (inside && !seen[static_cast<std::size_t>(j)] && open(j)) {
          seen.set(static_cast<std::size_t>(j));
          stack[static_cast<std::size_t>(top++)] = static_cast<std::uint16_t>(j);
        }
      };
      visit(x > 0, i - 1);
      visit(x < kLastCell, i + 1);
      visit(z > 0, i - kChunkSize);
      visit(z < kLastCell, i + kChunkSize);
      visit(y > 0, i - kChunkArea);
      visit(y < kLastCell, i + kChunkArea);
    }
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        if ((faces >> a & 1u) && (faces >> b & 1u)) links |= FaceLinks{1} << (a * 6 + b);
    if (links == kAllFacesLinked) break;
  }
  return links;
}

}  // namespace terrasol
