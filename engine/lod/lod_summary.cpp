#include "lod/lod_summary.h"

#include <algorithm>
#include <array>

namespace terrasol {

LodCell summarizeColumns(std::span<const LodColumn> columns) {
  LodCell cell;
  std::size_t wet = 0;
  int waterTop = kNoLodHeight;
  BlockId waterBlock = kAir;
  for (const LodColumn& c : columns) {
    if (c.top > cell.top) {
      cell.top = c.top;
      cell.surface = c.surface;
      cell.tint = c.tint;
    }
    if (c.water > c.top) {
      ++wet;
      if (c.water > waterTop) {
        waterTop = c.water;
        waterBlock = c.waterBlock;
      }
    }
  }
  if (2 * wet > columns.size()) {
    cell.water = waterTop;
    cell.waterBlock = waterBlock;
  }
  return cell;
}

LodTile sampleTile(LodTileKey key, const LodColumnSource& columnAt) {
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
          if (const auto c = columnAt(x0 + sx * stride + stride / 2, z0 + sz * stride + stride / 2))
            columns[n++] = *c;
        }
      tile.at(cx, cz) = summarizeColumns(std::span<const LodColumn>(columns.data(), n));
    }
  return tile;
}

}  // namespace terrasol
