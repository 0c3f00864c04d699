#pragma once
// Far terrain straight from the terrain generator: a tile's cells from the generator's column rules
// (TerrainGenerator::surfaceColumn) sampled at a few columns per cell, with no chunk made, so a
// world's horizon is there in moments. Caves, trees and plants are not sampled: from afar the ground's
// shape and colour are what shows.

#include "lod/lod_tile.h"
#include "world/terrain_generator.h"

namespace terrasol {

// Columns sampled per cell on each axis at most: every column up to cells of 4 blocks, then a
// stratified 4 x 4 of them (the highest of 16 keeps most ridges).
inline constexpr int kLodSamplesPerAxis = 4;

LodTile tileFromGenerator(const TerrainGenerator& generator, LodTileKey key);

}  // namespace terrasol
