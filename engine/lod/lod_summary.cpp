#include "lod/lod_summary.h"

#include <algorithm>
#include <array>

namespace terrasol {

LodCell summarizeColumns(std::span<const LodColumn> columns) {
  LodCell cell;
  // The block most columns show on top (the highest such column's among equal counts): a forest
  // cell with one crown in four columns stays grass-coloured, though the crown's height is kept.
  std::size_t mostShown = 0;
  int shownTop = kNoLodHeight;
  BlockId shown = kAir;
  for (const LodColumn& c : columns) {
    std::size_t n = 0;
    for (const LodColumn& o : columns) n += o.surface == c.surface ? 1 : 0;
    if (n > mostShown || (n == mostShown && c.top > shownTop))
      mostShown = n, shownTop = c.top, shown = c.surface;
  }
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
  if (cell.top != kNoLodHeight) cell.surface = shown;
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
