#include "lod/chunk_tiles.h"

#include <array>
#include <map>
#include <memory>
#include <utility>

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

LodTile tileFromHeldChunks(const ChunkGenerator& source, LodTileKey key, const BlockRegistry& blocks,
                           const LodColumnSource& edited) {
  using Columns = std::array<LodColumn, kChunkSize * kChunkSize>;
  std::map<std::pair<int, int>, std::unique_ptr<Columns>> made;  // null: a chunk the source does not hold
  return sampleTile(key, [&](int x, int z) -> std::optional<LodColumn> {
    if (edited) {
      if (std::optional<LodColumn> c = edited(x, z)) return c;
    }
    const ChunkPos pos = ChunkPos::of(BlockPos{x, 0, z});
    auto [it, first] = made.try_emplace({pos.x, pos.z});
    if (first && source.holdsChunk(pos)) {
      Chunk chunk(pos);
      source.generate(chunk);
      it->second = std::make_unique<Columns>();
      for (int cz = 0; cz < kChunkSize; ++cz)
        for (int cx = 0; cx < kChunkSize; ++cx)
          (*it->second)[static_cast<std::size_t>(cz * kChunkSize + cx)] = chunkColumn(chunk, cx, cz, blocks);
    }
    if (!it->second) return std::nullopt;
    const int column = (z - pos.minBlockZ()) * kChunkSize + (x - pos.minBlockX());
    return (*it->second)[static_cast<std::size_t>(column)];
  });
}

}  // namespace terrasol
