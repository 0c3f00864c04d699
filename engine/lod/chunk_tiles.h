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
#include "world/generator.h"

namespace terrasol {

// A chunk by position, or nullptr where there is none.
using ChunkLookup = std::function<const Chunk*(ChunkPos)>;

LodTile tileFromChunks(LodTileKey key, const ChunkLookup& chunkAt, const BlockRegistry& blocks);

// From a source that holds finished chunks (ChunkGenerator::holdsChunk: a Minecraft save): each chunk
// of the tile it holds is made whole once, on first need, and kept as its columns while the tile is
// sampled; the others stay empty. `edited` columns (the player's edits) are taken as they are.
LodTile tileFromHeldChunks(const ChunkGenerator& source, LodTileKey key, const BlockRegistry& blocks,
                           const LodColumnSource& edited = {});

// One column (x, z within the chunk) as tileFromChunks sees it.
LodColumn chunkColumn(const Chunk& chunk, int x, int z, const BlockRegistry& blocks);

}  // namespace terrasol
