#pragma once
// A far terrain tile as a mesh, in one of two shapes. Terraces: each cell's top (the water's surface on
// a wet cell, coloured as the water over its bed) at its height, walls down to lower neighbours, tops of
// one height and colour merged into rectangles; for a tile that meets full detail a top per cell and a
// wall on each side, even one of no height, because the renderer lowers the cells full detail covers
// and those walls then close the step down to them. A heightfield, for coarse cells: a vertex mid-cell
// at each cell's height, triangles between them, sides blending into steep slopes. Where a tile ends its edge
// hangs down to the world's floor (skirts): a neighbouring tile of another level, whatever its heights, meets
// them with no crack. Plain C++: built on worker threads, uploaded by the renderer.

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "core/tint_palette.h"
#include "lod/lod_tile.h"
#include "lod/lod_vertex.h"

namespace terrasol {

// A block's colours from afar: the average of its top and side textures (sRGB 0..1, untinted) and the
// tint each takes.
struct LodBlockColour {
  glm::vec3 top{0.5f}, side{0.5f};
  Tint topTint = Tint::None, sideTint = Tint::None;
  float opacity = 1.0f;  // its top texture's mean alpha: water lets its bed show through
};

// Every block's colours (by BlockId) and the pack's tint colours.
struct LodPalette {
  std::vector<LodBlockColour> blocks;
  TintPalette tints;

  // sRGB 0..1, tinted as in a column of `column`.
  glm::vec3 top(BlockId block, const ColumnTint& column) const;
  glm::vec3 side(BlockId block, const ColumnTint& column) const;
  float opacity(BlockId block) const;
  // A cell seen from above (water over its bed) and from the side.
  glm::vec3 surface(const LodCell& cell) const;
  glm::vec3 wall(const LodCell& cell) const;
};

struct LodMesh {
  LodTileKey key;
  // Terraces: quads, four corners each, counter-clockwise seen from outside. A heightfield: the
  // vertices `indices` makes triangles of, counter-clockwise too.
  std::vector<LodVertex> vertices;
  std::vector<std::uint16_t> indices;
  int minY = kMinY, maxY = kMinY;  // blocks: the box the mesh lies in (skirts reach kMinY)
  bool allWalls = false;           // terraces, meshed to meet full detail
  // Terraces' quads showing face d (Direction) are [faceStart[d], faceStart[d + 1]): a pass leaves out
  // the walls turned away from the camera for the whole tile.
  std::array<std::uint32_t, 7> faceStart{};
};

// Tiles of coarser cells than this draw as heightfields (unless full detail meets them): steps of 16
// blocks and more look like no terrain, while a surface through their cells keeps ridges' lines.
inline constexpr int kLodSmoothLevel = 4;

// Terraces where the tile touches full detail, has cells no source filled or is finer than
// kLodSmoothLevel, else a heightfield (see above).
LodMesh meshLodTile(const LodTile& tile, const LodPalette& palette, bool touchesFullDetail);
// `allWalls`: every wall, even of no height, and a top per cell (else tops merge into rectangles).
LodMesh meshLodTerraces(const LodTile& tile, const LodPalette& palette, bool allWalls);
LodMesh meshLodHeightfield(const LodTile& tile, const LodPalette& palette);

inline constexpr int kLodFloorY = kMinY * kLodYSteps;  // where skirts end

// Whether no source filled the cell (no ground, no water).
bool lodCellEmpty(const LodCell& cell);

// A cell's height as drawn, in 1/kLodYSteps block: its ground's top face, or its water's surface.
int lodSurfaceY(const LodCell& cell);

}  // namespace terrasol
