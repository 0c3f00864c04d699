// A far tile that never meets full detail as a heightfield (lod/lod_mesh.h): a vertex in the middle of
// every cell and a ring on the tile's edge, two triangles between each four, and skirts from the edge
// to the world's floor.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/octahedral.h"
#include "lod/lod_mesh.h"

namespace terrasol {
namespace {

constexpr int kSide = kLodTileCells + 2;  // vertices along a side: each cell's middle and both edges

// The grid's i-th place along a side in 1/kLodXZSteps cell, and the cell it takes its surface from.
int placeOf(int i) {
  if (i == 0) return 0;
  if (i == kSide - 1) return kLodTileCells * kLodXZSteps;
  return (i - 1) * kLodXZSteps + kLodXZSteps / 2;
}
int cellOf(int i) {
  return std::clamp(i - 1, 0, kLodTileCells - 1);
}

std::uint8_t unorm8(double v) {
  return static_cast<std::uint8_t>(std::lround((std::clamp(v, -1.0, 1.0) + 1.0) * 127.5));
}

class Builder {
 public:
  Builder(const LodTile& tile, const LodPalette& palette) : tile_(tile), palette_(palette) {}

  LodMesh build() {
    LodMesh mesh;
    mesh.key = tile_.key;
    int maxY = kLodFloorY;
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i) {
        mesh.vertices.push_back(surfaceVertex(i, j));
        maxY = std::max<int>(maxY, mesh.vertices.back().y);
      }
    for (int j = 0; j + 1 < kSide; ++j)
      for (int i = 0; i + 1 < kSide; ++i) {
        const std::uint16_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
        const auto y = [&](std::uint16_t v) { return mesh.vertices[v].y; };
        // Counter-clockwise from above; cut along the diagonal whose ends lie closer in height, so
        // ridges and valleys keep their line.
        if (std::abs(y(a) - y(c)) <= std::abs(y(b) - y(d)))
          mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        else
          mesh.indices.insert(mesh.indices.end(), {a, b, d, b, c, d});
      }
    skirt(mesh, Direction::West, [](int k) { return std::pair{0, k}; });
    skirt(mesh, Direction::East, [](int k) { return std::pair{kSide - 1, k}; });
    skirt(mesh, Direction::North, [](int k) { return std::pair{k, 0}; });
    skirt(mesh, Direction::South, [](int k) { return std::pair{k, kSide - 1}; });
    mesh.maxY = (maxY + kLodYSteps - 1) / kLodYSteps;
    return mesh;
  }

 private:
  static std::uint16_t at(int i, int j) { return static_cast<std::uint16_t>(j * kSide + i); }

  int heightOf(int cx, int cz) const {
    return lodSurfaceY(tile_.at(std::clamp(cx, 0, kLodTileCells - 1), std::clamp(cz, 0, kLodTileCells - 1)));
  }

  LodVertex surfaceVertex(int i, int j) const {
    const int cx = cellOf(i), cz = cellOf(j);
    const LodCell& cell = tile_.at(cx, cz);
    // The slope from the neighbours' heights (one-sided at the tile's edge), in blocks per block.
    const auto slope = [&](bool alongX) {
      const int c = alongX ? cx : cz;
      const int lo = std::max(c - 1, 0), hi = std::min(c + 1, kLodTileCells - 1);
      const int y0 = alongX ? heightOf(lo, cz) : heightOf(cx, lo),
                y1 = alongX ? heightOf(hi, cz) : heightOf(cx, hi);
      return static_cast<double>(y1 - y0) / (kLodYSteps * tile_.key.cellBlocks() * (hi - lo));
    };
    const double gx = slope(true), gz = slope(false);
    const glm::dvec2 normal = octEncode(glm::normalize(glm::dvec3(-gx, 1.0, -gz)));
    const bool wet = cell.water != kNoLodHeight;
    // A slope of g blocks a block is steps: of its area 1 / (1 + g) tops and g / (1 + g) sides. Lit,
    // the steps average the two normals, (0, 1, 0) and the side's, with those weights: the slope's
    // normal, but shorter, sqrt(1 + g^2) / (1 + g). The G-buffer takes a unit normal, so the colour
    // carries that length (a 45-degree slope of steps is 0.71 as bright as a smooth one).
    const double g = std::hypot(gx, gz);
    const glm::vec3 colour =
        wet ? palette_.surface(cell)
            : glm::mix(palette_.surface(cell), palette_.wall(cell), static_cast<float>(g / (1.0 + g))) *
                  static_cast<float>(std::sqrt(1.0 + g * g) / (1.0 + g));
    return {static_cast<std::int16_t>(placeOf(i)),
            static_cast<std::int16_t>(placeOf(j)),
            static_cast<std::int16_t>(lodSurfaceY(cell)),
            unorm8(normal.x),
            unorm8(normal.y),
            lodMaterial(colour, kLodFaceSmooth, wet)};
  }

  // The edge facing `d` hung down to the floor: edge(k) is the grid place of its k-th vertex.
  template <typename Edge>
  void skirt(LodMesh& mesh, Direction d, Edge edge) const {
    const BlockPos out = kDirectionOffsets[static_cast<int>(d)];
    const std::size_t first = mesh.vertices.size();
    for (int k = 0; k < kSide; ++k) {
      const auto [i, j] = edge(k);
      LodVertex v = mesh.vertices[at(i, j)];
      v.y = kLodFloorY;
      v.cellX = v.cellZ = 0;
      v.material =
          lodMaterial(palette_.wall(tile_.at(cellOf(i), cellOf(j))), static_cast<std::uint32_t>(d), false);
      mesh.vertices.push_back(v);
    }
    const auto position = [&](std::uint16_t v) {
      const LodVertex& p = mesh.vertices[v];
      return glm::dvec3(p.x, p.y, p.z);
    };
    for (int k = 0; k + 1 < kSide; ++k) {
      const auto [i0, j0] = edge(k);
      const auto [i1, j1] = edge(k + 1);
      const std::uint16_t top0 = at(i0, j0), top1 = at(i1, j1);
      const auto bottom0 = static_cast<std::uint16_t>(first + static_cast<std::size_t>(k)),
                 bottom1 = static_cast<std::uint16_t>(bottom0 + 1);
      // Wound to face out: the order is checked against the outward normal rather than worked out per side.
      std::array<std::uint16_t, 4> q = {bottom0, bottom1, top1, top0};
      const glm::dvec3 n = glm::cross(position(q[1]) - position(q[0]), position(q[2]) - position(q[0]));
      if (glm::dot(n, glm::dvec3(out.x, out.y, out.z)) < 0.0) std::swap(q[1], q[3]);
      mesh.indices.insert(mesh.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
  }

  const LodTile& tile_;
  const LodPalette& palette_;
};

}  // namespace

LodMesh meshLodHeightfield(const LodTile& tile, const LodPalette& palette) {
  return Builder(tile, palette).build();
}

}  // namespace terrasol
