#pragma once
// Far terrain straight from a chunk generator: a tile's cells from its column rule
// (ChunkGenerator::surfaceColumn) at the sampled columns, with no chunk made, so a world's horizon is
// there in moments. Caves, trees and plants are not sampled: from afar the ground's shape and colour
// are what shows. A generator with no column rule leaves the cells empty.

#include "lod/lod_tile.h"
#include "world/generator.h"

namespace terrasol {

LodTile tileFromGenerator(const ChunkGenerator& generator, LodTileKey key);

}  // namespace terrasol
