#pragma once
// Far terrain from chunks already made (generated, edited, loaded from a save): each sampled column's
// ground is its highest cube that is not translucent (stone, grass, leaves), the water over it the
// highest liquid or translucent cube above (water, lava, ice); plants, torches and other shapes are too small
// to show from afar. Cells whose chunks are not there stay empty for the generator to fill.

#include <functional>

#include "lod/lod_summary.h"
#include "lod/lod_tile.h"
#include "world/block_registry.h"
#include "world/chunk.h"

namespace terrasol {

// A chunk by position, or nullptr where there is none.
using ChunkLookup = std::function<const Chunk*(ChunkPos)>;

LodTile tileFromChunks(LodTileKey key, const ChunkLookup& chunkAt, const BlockRegistry& blocks);

// One column (x, z within the chunk) as tileFromChunks sees it.
LodColumn chunkColumn(const Chunk& chunk, int x, int z, const BlockRegistry& blocks);

}  // namespace terrasol
