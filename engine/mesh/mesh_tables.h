#pragma once
// The mesher's constant tables: each face's frame in integers, the snapshot steps to neighbours and,
// per face corner, the cells whose light it sums and its position and UV within its block. Internal
// to engine/mesh.

#include <array>
#include <cstdint>

#include "core/model_units.h"
#include "mesh/mesh_data.h"
#include "mesh/section_snapshot.h"

namespace terrasol::mesh_tables {

struct Vec {
  int x, y, z;
};

// Per face (Direction order), from kFaceBases in integers: the normal n and tangents t, b with
// t x b = n, so corners taken as (-,-) (+,-) (+,+) (-,+) in (t, b) run counter-clockwise seen from
// outside. u runs along t and v against b (v = 0 at the texture's top).
struct FaceFrame {
  Vec n, t, b;
};
constexpr Vec toVec(const float (&v)[3]) {
  return {static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2])};
}
constexpr auto kFaces = [] {
  std::array<FaceFrame, 6> faces{};
  for (int d = 0; d < 6; ++d) {
    const FaceBasis& b = kFaceBases[d];
    faces[static_cast<std::size_t>(d)] = {toVec(b.normal), toVec(b.tangent), toVec(b.up)};
  }
  return faces;
}();

constexpr int offset(int dx, int dy, int dz) {
  return dx + dz * SectionSnapshot::kSide + dy * SectionSnapshot::kSide * SectionSnapshot::kSide;
}

// Snapshot index step to the neighbour in each Direction.
constexpr auto kNeighbour = [] {
  std::array<int, 6> steps{};
  for (int d = 0; d < 6; ++d)
    steps[static_cast<std::size_t>(d)] = offset(kFaces[d].n.x, kFaces[d].n.y, kFaces[d].n.z);
  return steps;
}();

// Per face and corner: snapshot index offsets (from the cell in front of the face) of the two cells
// beside the corner and the diagonal one, the corner's position within its block (1/32) and its UV.
struct CornerCells {
  int side1, side2, diagonal;
  std::uint32_t position;  // PackedVertex::packPosition of the corner within its block
  bool top;                // on the block's top, where a lowered liquid surface moves it
  std::uint32_t uv;
};
constexpr auto kCorners = [] {
  std::array<std::array<CornerCells, 4>, 6> table{};
  for (int d = 0; d < 6; ++d)
    for (int c = 0; c < 4; ++c) {
      const FaceFrame& f = kFaces[d];
      const int su = kCornerSigns[c][0], sv = kCornerSigns[c][1];
      const Vec a{su * f.t.x, su * f.t.y, su * f.t.z}, b{sv * f.b.x, sv * f.b.y, sv * f.b.z};
      const int y32 = 16 + 16 * (f.n.y + a.y + b.y);
      table[d][c] = {
          offset(a.x, a.y, a.z),
          offset(b.x, b.y, b.z),
          offset(a.x + b.x, a.y + b.y, a.z + b.z),
          PackedVertex::packPosition(16 + 16 * (f.n.x + a.x + b.x), y32, 16 + 16 * (f.n.z + a.z + b.z)),
          y32 == 32,
          PackedVertex::packUv(su > 0 ? kModelUnits : 0, sv > 0 ? 0 : kModelUnits)};
    }
  return table;
}();

}  // namespace terrasol::mesh_tables
