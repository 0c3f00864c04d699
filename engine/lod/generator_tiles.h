#pragma once
// Far terrain straight from a chunk generator: a tile's cells from its column rule
// (ChunkGenerator::surfaceColumn) at the sampled columns, with no chunk made, so a world's horizon is
// there in moments, with the crowns of the trees it would grow (ChunkGenerator::treeCrowns) over it.
// Caves and plants are not sampled: from afar the ground's shape and colour are what shows. A
// generator with no column rule leaves the cells empty.

#include "lod/lod_summary.h"
#include "lod/lod_tile.h"
#include "world/block_registry.h"
#include "world/generator.h"

namespace terrasol {

// `edited`: columns that differ from the generator's now (the player's edits), taken as they are.
LodTile tileFromGenerator(const ChunkGenerator& generator, LodTileKey key,
                          const LodColumnSource& edited = {});

// Whether far terrain can show what `source` makes: by its column rule, or from the chunks it holds.
bool lodCanSample(const ChunkGenerator& source);
// A tile by the column rule where there is one, else from the chunks the source holds
// (lod/chunk_tiles.h).
LodTile tileFromSource(const ChunkGenerator& source, LodTileKey key, const BlockRegistry& blocks,
                       const LodColumnSource& edited = {});

}  // namespace terrasol
