#include "lod/lod_summary.h"

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

}  // namespace terrasol
