#include "lod/lod_mesh.h"

#include <algorithm>
#include <array>
#include <glm/common.hpp>

namespace terrasol {
namespace {

glm::vec3 tinted(glm::vec3 texture, Tint tint, const TintPalette& tints, const ColumnTint& column) {
  return texture * tints.colour(tint, column);
}

// A corner as the quad builder sees it: place (cells, 1/kLodYSteps block) and the cell it follows.
struct Corner {
  int x, y, z;
  int cellX, cellZ;  // -1..kLodTileCells
};

// Quads gathered by the face they show, then laid out face after face (LodMesh::faceStart).
class QuadWriter {
 public:
  // Four corners counter-clockwise seen from outside.
  void quad(const std::array<Corner, 4>& c, std::uint32_t material) {
    std::vector<LodVertex>& out = byFace_[(material >> kLodFaceShift) & 7u];
    for (const Corner& k : c) {
      out.push_back({static_cast<std::int16_t>(k.x * kLodXZSteps),
                     static_cast<std::int16_t>(k.z * kLodXZSteps), static_cast<std::int16_t>(k.y),
                     static_cast<std::uint8_t>(k.cellX + 1), static_cast<std::uint8_t>(k.cellZ + 1),
                     material});
    }
  }
  void finish(LodMesh& mesh) const {
    for (std::size_t f = 0; f < byFace_.size(); ++f) {
      mesh.faceStart[f] = static_cast<std::uint32_t>(mesh.vertices.size() / 4);
      mesh.vertices.insert(mesh.vertices.end(), byFace_[f].begin(), byFace_[f].end());
    }
    mesh.faceStart[byFace_.size()] = static_cast<std::uint32_t>(mesh.vertices.size() / 4);
  }

 private:
  std::array<std::vector<LodVertex>, 6> byFace_;
};

struct Top {
  int y = kLodFloorY;
  std::uint32_t material = 0;  // 0: no top (an empty cell, or one drawn already)
  bool operator==(const Top&) const = default;
};

// Greedy rectangles: a run along x, grown along z while every cell of the next row matches it.
void mergeTops(std::vector<Top>& tops, QuadWriter& out) {
  const auto at = [&](int x, int z) -> Top& { return tops[static_cast<std::size_t>(z * kLodTileCells + x)]; };
  for (int z0 = 0; z0 < kLodTileCells; ++z0)
    for (int x0 = 0; x0 < kLodTileCells; ++x0) {
      const Top t = at(x0, z0);
      if (t.material == 0) continue;
      int x1 = x0 + 1;
      while (x1 < kLodTileCells && at(x1, z0) == t) ++x1;
      int z1 = z0 + 1;
      for (; z1 < kLodTileCells; ++z1) {
        bool same = true;
        for (int x = x0; x < x1 && same; ++x) same = at(x, z1) == t;
        if (!same) break;
      }
      for (int z = z0; z < z1; ++z)
        for (int x = x0; x < x1; ++x) at(x, z).material = 0;
      out.quad({Corner{x0, t.y, z0, x0, z0},
                {x0, t.y, z1, x0, z1 - 1},
                {x1, t.y, z1, x1 - 1, z1 - 1},
                {x1, t.y, z0, x1 - 1, z0}},
               t.material);
    }
}

}  // namespace

glm::vec3 LodPalette::top(BlockId block, const ColumnTint& column) const {
  if (block >= blocks.size()) return glm::vec3(0.5f);
  const LodBlockColour& c = blocks[block];
  return tinted(c.top, c.topTint, tints, column);
}

float LodPalette::opacity(BlockId block) const {
  return block < blocks.size() ? blocks[block].opacity : 1.0f;
}

glm::vec3 LodPalette::side(BlockId block, const ColumnTint& column) const {
  if (block >= blocks.size()) return glm::vec3(0.5f);
  const LodBlockColour& c = blocks[block];
  return tinted(c.side, c.sideTint, tints, column);
}

glm::vec3 LodPalette::surface(const LodCell& cell) const {
  const glm::vec3 ground = top(cell.surface, cell.tint);
  if (cell.water == kNoLodHeight) return ground;
  // Water over its bed, as the translucent pass blends it (lit alike, as far terrain is).
  return glm::mix(ground, top(cell.waterBlock, cell.tint), opacity(cell.waterBlock));
}

glm::vec3 LodPalette::wall(const LodCell& cell) const {
  return cell.water != kNoLodHeight ? side(cell.waterBlock, cell.tint) : side(cell.surface, cell.tint);
}

int lodSurfaceY(const LodCell& cell) {
  if (cell.water != kNoLodHeight) return (cell.water + 1) * kLodYSteps - 1;
  if (cell.top == kNoLodHeight) return kLodFloorY;
  return (cell.top + 1) * kLodYSteps;
}

bool lodCellEmpty(const LodCell& cell) {
  return cell.top == kNoLodHeight && cell.water == kNoLodHeight;
}

LodMesh meshLodTile(const LodTile& tile, const LodPalette& palette, bool touchesFullDetail) {
  // A cell no source filled (a save's missing chunk) is a hole a heightfield has no shape for.
  const bool holes = std::any_of(tile.cells.begin(), tile.cells.end(), lodCellEmpty);
  if (touchesFullDetail || holes) return meshLodTerraces(tile, palette, true);
  return tile.key.level < kLodSmoothLevel ? meshLodTerraces(tile, palette, false)
                                          : meshLodHeightfield(tile, palette);
}

LodMesh meshLodTerraces(const LodTile& tile, const LodPalette& palette, bool allWalls) {
  LodMesh mesh;
  mesh.key = tile.key;
  mesh.allWalls = allWalls;
  QuadWriter out;
  const auto inside = [](int cx, int cz) {
    return cx >= 0 && cz >= 0 && cx < kLodTileCells && cz < kLodTileCells;
  };
  int maxY = kLodFloorY;
  // Tops of a tile that never meets full detail merge into rectangles of one height and colour (a
  // sea, a plain); a tile that does keeps one per cell, as each may sink on its own.
  std::vector<Top> tops(static_cast<std::size_t>(kLodTileCells * kLodTileCells));
  for (int cz = 0; cz < kLodTileCells; ++cz)
    for (int cx = 0; cx < kLodTileCells; ++cx) {
      const LodCell& cell = tile.at(cx, cz);
      if (lodCellEmpty(cell)) continue;
      const bool wet = cell.water != kNoLodHeight;
      const int y = lodSurfaceY(cell);
      maxY = std::max(maxY, y);
      const std::uint32_t topMaterial =
          lodMaterial(palette.surface(cell), static_cast<std::uint32_t>(Direction::Up), wet);
      if (allWalls) {
        out.quad({Corner{cx, y, cz, cx, cz},
                  {cx, y, cz + 1, cx, cz},
                  {cx + 1, y, cz + 1, cx, cz},
                  {cx + 1, y, cz, cx, cz}},
                 topMaterial);
      } else {
        tops[static_cast<std::size_t>(cz * kLodTileCells + cx)] = {y, topMaterial};
      }
      const glm::vec3 side = palette.wall(cell);
      for (const Direction d : {Direction::West, Direction::East, Direction::North, Direction::South}) {
        const BlockPos o = kDirectionOffsets[static_cast<int>(d)];
        const int nx = cx + o.x, nz = cz + o.z;
        int bottom = kLodFloorY;  // a skirt: beyond the tile, or next to a cell no source has filled
        if (inside(nx, nz) && !lodCellEmpty(tile.at(nx, nz))) {
          bottom = std::min(lodSurfaceY(tile.at(nx, nz)), y);
          if (bottom == y && !allWalls) continue;
        }
        // The edge facing d, from the end on the left to the one on the right seen from outside
        // (right = -d x up), so the wall is counter-clockwise whatever its height, even none.
        const int ex = o.x > 0 ? cx + 1 : cx, ez = o.z > 0 ? cz + 1 : cz;
        const int lx = o.z != 0 ? (o.z > 0 ? cx : cx + 1) : ex, lz = o.x != 0 ? (o.x > 0 ? cz + 1 : cz) : ez;
        const int rx = o.z != 0 ? (o.z > 0 ? cx + 1 : cx) : ex, rz = o.x != 0 ? (o.x > 0 ? cz : cz + 1) : ez;
        out.quad({Corner{lx, bottom, lz, nx, nz},
                  {rx, bottom, rz, nx, nz},
                  {rx, y, rz, cx, cz},
                  {lx, y, lz, cx, cz}},
                 lodMaterial(side, static_cast<std::uint32_t>(d), wet));
      }
    }
  mergeTops(tops, out);
  out.finish(mesh);
  mesh.maxY = (maxY + kLodYSteps - 1) / kLodYSteps;
  return mesh;
}

}  // namespace terrasol
