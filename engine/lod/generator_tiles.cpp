#include "lod/generator_tiles.h"

#include "lod/lod_summary.h"

namespace terrasol {

LodTile tileFromGenerator(const TerrainGenerator& generator, LodTileKey key) {
  return sampleTile(key, [&](int x, int z) -> std::optional<LodColumn> {
    const SurfaceColumn c = generator.surfaceColumn(x, z);
    return LodColumn{c.height, c.top, c.water, c.waterBlock};
  });
}

}  // namespace terrasol
