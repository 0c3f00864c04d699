#pragma once
// A far terrain tile as quads: each cell's top (the water's surface on a wet cell, coloured as the water
// over its bed) at its height, and
// walls down to lower neighbours, so a slope of cells reads as terraces with no gap between them. Where
// the tile ends the walls go down to the world's floor (skirts): a neighbouring tile of another level,
// whatever its heights, meets them with no crack. A tile that touches full detail gets every wall,
// even those of no height, because the renderer lowers the cells full detail covers and those walls then
// close the step down to them. Plain C++: built on worker threads, uploaded by the renderer.

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
};

struct LodMesh {
  LodTileKey key;
  std::vector<LodVertex> vertices;  // quads, four corners each, counter-clockwise seen from outside
  int minY = 0, maxY = 0;           // blocks: the box the quads lie in (skirts reach kMinY)
  bool allWalls = false;            // meshed to meet full detail
  // The quads showing face d (Direction) are [faceStart[d], faceStart[d + 1]): a pass leaves out the
  // walls turned away from the camera for the whole tile.
  std::array<std::uint32_t, 7> faceStart{};
};

// `allWalls`: the tile touches full detail (see above).
LodMesh meshLodTile(const LodTile& tile, const LodPalette& palette, bool allWalls);

// A cell's height as drawn, in 1/kLodYSteps block: its ground's top face, or its water's surface.
int lodSurfaceY(const LodCell& cell);

}  // namespace terrasol
