#pragma once
// Which far terrain tiles to draw round a camera: a quadtree over the square out to the far edge,
// whose tiles split while they lie nearer than `detail` times their own width, so every tile looks
// about as large on screen (cells shrink to `minLevel`'s towards the camera). Tiles wholly inside full
// detail are left out; those that reach into it are split down to cells a chunk wide, so full detail
// hides them cell by cell. The leaves cover the disc to the far edge once, with no overlap.

#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include "lod/lod_tile.h"

namespace terrasol {

inline constexpr int kLodChunkLevel = 4;  // cells as wide as a chunk
inline constexpr int kLodMaxLevel = 12;

// Full detail: the chunks [min, max] on x and z, both ends included.
struct ChunkSquare {
  glm::ivec2 min{0}, max{-1};
  bool contains(glm::ivec2 c) const { return c.x >= min.x && c.y >= min.y && c.x <= max.x && c.y <= max.y; }
};

struct LodView {
  glm::dvec2 camera{0.0};  // x, z in blocks
  double distance = 0.0;   // blocks to the far edge
  // Where full detail may draw (the renderer's mask of covered chunks lies within it), and the part of
  // that it draws whole: tiles inside `covered` are left out.
  std::optional<ChunkSquare> reach, covered;
};

struct LodLevels {
  int minLevel = 1;     // the finest cells, 2^minLevel blocks
  double detail = 2.0;  // a tile splits while nearer than detail x its width
};

struct LodSelected {
  LodTileKey key;
  bool touchesFullDetail = false;  // reaches into full detail's reach (or borders it)
  bool operator==(const LodSelected&) const = default;
};

// Nearest first.
std::vector<LodSelected> selectLodTiles(const LodView& view, const LodLevels& levels);

}  // namespace terrasol
