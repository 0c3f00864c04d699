#include "lod/generator_tiles.h"

#include "lod/lod_summary.h"

namespace terrasol {

LodTile tileFromGenerator(const ChunkGenerator& generator, LodTileKey key) {
  return sampleTile(key, [&](int x, int z) -> std::optional<LodColumn> {
    const std::optional<SurfaceColumn> c = generator.surfaceColumn(x, z);
    if (!c) return std::nullopt;
    return LodColumn{c->height, c->top, c->water, c->waterBlock, climateOnly(c->climate)};
  });
}

}  // namespace terrasol
