#pragma once
// A cell's summary of the columns it covers, whatever their source (the generator, loaded chunks).

#include <span>

#include "lod/lod_tile.h"

namespace terrasol {

// One column as a source sees it: its ground's top and the water over it (LodCell's fields).
using LodColumn = LodCell;

// The cell over `columns`: its top is the highest column's, so ridges and peaks keep their height from
// afar (a mean would sink them into the hills), the block on it that column's; water where it lies
// over more than half the columns, at the highest such surface, so a coast stays where it is and a
// puddle does not flood its cell. No columns, or none with ground: an empty cell.
LodCell summarizeColumns(std::span<const LodColumn> columns);

}  // namespace terrasol
