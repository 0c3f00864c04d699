#pragma once
// Far terrain straight from the terrain generator: a tile's cells from the generator's column rule
// (TerrainGenerator::surfaceColumn) at the sampled columns, with no chunk made, so a world's horizon is
// there in moments. Caves, trees and plants are not sampled: from afar the ground's shape and colour
// are what shows.

#include "lod/lod_tile.h"
#include "world/terrain_generator.h"

namespace terrasol {

LodTile tileFromGenerator(const TerrainGenerator& generator, LodTileKey key);

}  // namespace terrasol
