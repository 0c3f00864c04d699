#include "world/world.h"

namespace terrasol {

BlockId World::getBlock(const BlockPos& pos) const {
  if (!inWorldHeight(pos.y) || !insideBorder(pos)) return kAir;
  const Chunk* c = chunk(ChunkPos::of(pos));
  return c ? c->get(localOf(pos.x), pos.y, localOf(pos.z)) : kAir;
}

std::optional<BlockChange> World::setBlock(const BlockPos& pos, BlockId id) {
  if (!inWorldHeight(pos.y) || !insideBorder(pos)) return std::nullopt;
  Chunk* c = chunk(ChunkPos::of(pos));
  if (!c) return std::nullopt;
  const BlockId before = c->set(localOf(pos.x), pos.y, localOf(pos.z), id);
  if (before == id) return std::nullopt;
  c->setModified(true);
  return BlockChange{pos, before, id};
}

Chunk* World::chunk(ChunkPos pos) {
  const auto it = chunks_.find(pos);
  return it == chunks_.end() ? nullptr : it->second.get();
}

const Chunk* World::chunk(ChunkPos pos) const {
  const auto it = chunks_.find(pos);
  return it == chunks_.end() ? nullptr : it->second.get();
}

Chunk& World::insertChunk(std::unique_ptr<Chunk> chunk) {
  auto& slot = chunks_[chunk->pos()];
  slot = std::move(chunk);
  return *slot;
}

std::unique_ptr<Chunk> World::removeChunk(ChunkPos pos) {
  const auto it = chunks_.find(pos);
  if (it == chunks_.end()) return nullptr;
  auto chunk = std::move(it->second);
  chunks_.erase(it);
  return chunk;
}

}  // namespace terrasol
