#include "lod/generator_tiles.h"

#include <algorithm>
#include <cstdlib>
#include <unordered_map>
#include <vector>

#include "lod/chunk_tiles.h"
#include "lod/lod_summary.h"

namespace terrasol {

LodTile tileFromGenerator(const ChunkGenerator& generator, LodTileKey key, const LodColumnSource& edited) {
  // Tree crowns by the chunk they are rooted in, asked once per tile.
  std::unordered_map<ChunkPos, std::vector<TreeCrown>> crowns;
  const auto crownsOf = [&](ChunkPos at) -> const std::vector<TreeCrown>& {
    auto [it, added] = crowns.try_emplace(at);
    if (added) generator.treeCrowns(at, it->second);
    return it->second;
  };
  constexpr int kReach = 3;  // the widest crown's radius
  return sampleTile(key, [&](int x, int z) -> std::optional<LodColumn> {
    if (edited) {
      if (std::optional<LodColumn> e = edited(x, z)) return e;
    }
    const std::optional<SurfaceColumn> c = generator.surfaceColumn(x, z);
    if (!c) return std::nullopt;
    LodColumn column{c->height, c->top, c->water, c->waterBlock, climateOnly(c->climate)};
    for (int cz = chunkOf(z - kReach); cz <= chunkOf(z + kReach); ++cz)
      for (int cx = chunkOf(x - kReach); cx <= chunkOf(x + kReach); ++cx)
        for (const TreeCrown& t : crownsOf({cx, cz})) {
          const int d = std::max(std::abs(t.x - x), std::abs(t.z - z));
          const int top = d <= t.radius ? t.top : d <= t.wideRadius ? t.wideTop : kNoLodHeight;
          if (top <= column.top) continue;
          column.top = top;
          column.surface = t.leaves;
        }
    return column;
  });
}

bool lodCanSample(const ChunkGenerator& source) {
  return source.surfaceColumn(0, 0).has_value() || source.holdsChunks();
}

LodTile tileFromSource(const ChunkGenerator& source, LodTileKey key, const BlockRegistry& blocks,
                       const LodColumnSource& edited) {
  if (source.surfaceColumn(0, 0)) return tileFromGenerator(source, key, edited);
  return tileFromHeldChunks(source, key, blocks, edited);
}

}  // namespace terrasol
