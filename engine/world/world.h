#pragma once
// The loaded world: a map of chunks keyed by chunk coordinates. Main thread only; worker threads get
// copies (chunk generation builds fresh chunks, meshing takes snapshots).

#include <memory>
#include <optional>
#include <unordered_map>

#include "world/block_registry.h"
#include "world/block_shapes.h"
#include "world/chunk.h"

namespace terrasol {

struct BlockChange {
  BlockPos pos;
  BlockId before = kAir;
  BlockId after = kAir;
};

class World {
 public:
  // `shapes`: the states' shapes (collision, targeting, light through shaped blocks), which must
  // outlive the world; without them cubes are whole cells and nothing else has a shape.
  explicit World(const BlockRegistry& blocks, const BlockShapes* shapes = nullptr)
      : blocks_(&blocks), shapes_(shapes) {}

  const BlockRegistry& blocks() const { return *blocks_; }
  void setShapes(const BlockShapes* shapes) { shapes_ = shapes; }
  const BlockShapes* shapes() const { return shapes_; }
  // Per state, 1 for an opaque cube (BlockShapes::opaqueCubes, or the registry's without shapes).
  const std::vector<std::uint8_t>& opaqueCubes() const {
    return shapes_ ? shapes_->opaqueCubes() : blocks_->opaqueCubes();
  }

  // Air outside the world height, beyond the border or in a chunk that is not loaded.
  BlockId getBlock(const BlockPos& pos) const;
  BlockId neighbour(const BlockPos& pos, Direction d) const {
    const BlockPos& o = kDirectionOffsets[static_cast<int>(d)];
    return getBlock(pos.offset(o.x, o.y, o.z));
  }
  // Sets a block and reports the change; nothing (and no change) when the block is already `id`, the
  // position is outside the world height or border, or its chunk is not loaded.
  std::optional<BlockChange> setBlock(const BlockPos& pos, BlockId id);

  bool isLoaded(ChunkPos pos) const { return chunks_.contains(pos); }
  Chunk* chunk(ChunkPos pos);
  const Chunk* chunk(ChunkPos pos) const;
  // Adds or replaces a chunk.
  Chunk& insertChunk(std::unique_ptr<Chunk> chunk);
  // Removes a chunk and hands it back (null when not loaded).
  std::unique_ptr<Chunk> removeChunk(ChunkPos pos);
  std::size_t chunkCount() const { return chunks_.size(); }

  template <class F>
  void forEachChunk(F&& f) const {
    for (const auto& [pos, chunk] : chunks_) f(static_cast<const Chunk&>(*chunk));
  }
  template <class F>
  void forEachChunk(F&& f) {
    for (auto& [pos, chunk] : chunks_) f(*chunk);
  }

 private:
  const BlockRegistry* blocks_;
  const BlockShapes* shapes_ = nullptr;
  std::unordered_map<ChunkPos, std::unique_ptr<Chunk>> chunks_;
};

constexpr bool insideBorder(const BlockPos& p) {
  return p.x >= -kWorldBorder && p.x < kWorldBorder && p.z >= -kWorldBorder && p.z < kWorldBorder;
}

}  // namespace terrasol
