#include "lod/chunk_tiles.h"

#include "lod/lod_summary.h"

namespace terrasol {

LodColumn chunkColumn(const Chunk& chunk, int x, int z, const BlockRegistry& blocks) {
  LodColumn column;
  column.tint = chunk.tint(x, z);
  for (int y = kMaxY - 1; y >= kMinY; --y) {
    const BlockId id = chunk.get(x, y, z);
    if (id == kAir) continue;
    const BlockType& type = blocks[id];
    if (type.shape == BlockShape::Liquid ||
        (type.shape == BlockShape::Cube && type.layer == RenderLayer::Translucent)) {
      if (column.water == kNoLodHeight) {
        column.water = y;
        column.waterBlock = id;
      }
      continue;
    }
    if (type.shape != BlockShape::Cube) continue;
    column.top = y;
    column.surface = id;
    break;
  }
  return column;
}

LodTile tileFromChunks(LodTileKey key, const ChunkLookup& chunkAt, const BlockRegistry& blocks) {
  return sampleTile(key, [&](int x, int z) -> std::optional<LodColumn> {
    const ChunkPos pos = ChunkPos::of(BlockPos{x, 0, z});
    const Chunk* chunk = chunkAt(pos);
    if (!chunk) return std::nullopt;
    return chunkColumn(*chunk, x - pos.minBlockX(), z - pos.minBlockZ(), blocks);
  });
}

}  // namespace terrasol
