#include "lod/generator_tiles.h"

#include <algorithm>
#include <array>

#include "lod/lod_summary.h"

namespace terrasol {

LodTile tileFromGenerator(const TerrainGenerator& generator, LodTileKey key) {
  LodTile tile{key, {}};
  const int cell = key.cellBlocks();
  const int samples = std::min(cell, kLodSamplesPerAxis);
  const int stride = cell / samples;  // both powers of two
  std::array<LodColumn, kLodSamplesPerAxis * kLodSamplesPerAxis> columns{};
  for (int cz = 0; cz < kLodTileCells; ++cz)
    for (int cx = 0; cx < kLodTileCells; ++cx) {
      const int x0 = key.minBlockX() + cx * cell, z0 = key.minBlockZ() + cz * cell;
      std::size_t n = 0;
      for (int sz = 0; sz < samples; ++sz)
        for (int sx = 0; sx < samples; ++sx) {
          // The middle of each stratum.
          const SurfaceColumn c =
              generator.surfaceColumn(x0 + sx * stride + stride / 2, z0 + sz * stride + stride / 2);
          columns[n++] = {c.height, c.top, c.water, c.waterBlock};
        }
      tile.at(cx, cz) = summarizeColumns(std::span<const LodColumn>(columns.data(), n));
    }
  return tile;
}

}  // namespace terrasol
