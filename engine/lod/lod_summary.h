#pragma once
// A cell's summary of the columns it covers, whatever their source (the generator, loaded chunks), and
// the sampling of a tile's columns that every source shares.

#include <functional>
#include <optional>
#include <span>

#include "lod/lod_tile.h"

namespace terrasol {

// One column as a source sees it: its ground's top and the water over it (LodCell's fields).
using LodColumn = LodCell;

// The cell over `columns`: its top is the highest column's, so ridges and peaks keep their height from
// afar (a mean would sink them into the hills), the block on it the one most columns show (a lone
// tree's crown does not paint its cell leaves); water where it lies
// over more than half the columns, at the highest such surface, so a coast stays where it is and a
// puddle does not flood its cell. No columns, or none with ground: an empty cell.
LodCell summarizeColumns(std::span<const LodColumn> columns);

// Columns sampled per cell on each axis at most: every column up to cells of 4 blocks, then a
// stratified 4 x 4 of them, each stratum's middle (the highest of 16 keeps most ridges).
inline constexpr int kLodSamplesPerAxis = 4;

// A column (world x, z) from a source; nothing where the source has none (a chunk not loaded).
using LodColumnSource = std::function<std::optional<LodColumn>(int x, int z)>;

// Every cell of the tile from its sampled columns; a cell none of whose columns the source has stays
// empty (top kNoLodHeight), for another source to fill.
LodTile sampleTile(LodTileKey key, const LodColumnSource& columnAt);

}  // namespace terrasol
