#pragma once
// A Minecraft save as a chunk source of the streamed world, in the place of a generator: a chunk the
// save holds finished comes from it; anywhere else (never generated, a proto-chunk, a damaged chunk)
// is left empty. Cells of a block nothing knows hold the registry's "unknown_block" (the missing
// texture), never air. Worker threads call generate() at once; each takes a mapper of its own.

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "minecraft/minecraft_save.h"
#include "world/generator.h"

namespace terrasol {

class MinecraftChunkSource : public ChunkGenerator {
 public:
  // Throws Error as MinecraftSave does.
  MinecraftChunkSource(const std::filesystem::path& dir, const BlockRegistry& blocks);

  void generate(Chunk& chunk) const override;
  int surfaceHeight(int x, int z) const override;
  // Each column's biome tint, where its highest block stands (a chunk of the overlay's save).
  void fillTints(Chunk& chunk) const override;

  const MinecraftSave& save() const { return save_; }
  // Where a player starts: the save's single player, else its spawn, else above the middle of its
  // finished chunks (a bare region folder).
  glm::dvec3 startPosition() const;

  // Counted over the chunks made so far.
  std::size_t unknownCells() const { return unknownCells_; }
  // The save's header problems, then each damaged chunk's, named by file and chunk.
  std::vector<std::string> problems() const;

 private:
  // The save's finished chunk, or null (counted and reported as generate() says).
  std::unique_ptr<Chunk> read(ChunkPos pos) const;
  std::unique_ptr<BlockStateMapper> takeMapper() const;
  void giveBack(std::unique_ptr<BlockStateMapper> mapper) const;

  MinecraftSave save_;
  const BlockRegistry& blocks_;
  BlockId placeholder_;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<BlockStateMapper>> mappers_;
  mutable std::vector<std::string> problems_;
  mutable std::atomic<std::size_t> unknownCells_ = 0;
};

}  // namespace terrasol
