#pragma once
// A Minecraft save as a chunk source of the streamed world, in the place of a generator: a chunk the
// save holds finished comes from it; anywhere else (never generated, a proto-chunk, a damaged chunk)
// is left empty. Cells of a block nothing knows hold the registry's "unknown_block" (the missing
// texture), never air. Biome tints are blended across chunk borders as Minecraft blends them, from
// the neighbours' biomes (read once and kept). Worker threads call generate() at once; each takes a
// mapper of its own.

#include <atomic>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "minecraft/biome_blend.h"
#include "minecraft/minecraft_save.h"
#include "world/generator.h"

namespace terrasol {

class MinecraftChunkSource : public ChunkGenerator {
 public:
  // Throws Error as MinecraftSave does.
  MinecraftChunkSource(const std::filesystem::path& dir, const BlockRegistry& blocks);

  void generate(Chunk& chunk) const override;
  int surfaceHeight(int x, int z) const override;
  // Each column's biome tint, blended (a chunk of the overlay's save).
  void fillTints(Chunk& chunk) const override;
  bool holdsChunks() const override { return true; }
  bool holdsChunk(ChunkPos pos) const override { return save_.contains(pos); }

  const MinecraftSave& save() const { return save_; }
  // Where a player starts: the save's single player, else its spawn, else above the middle of its
  // finished chunks (a bare region folder).
  glm::dvec3 startPosition() const;

  // Counted over the chunks made so far.
  std::size_t unknownCells() const { return unknownCells_; }
  // The save's header problems, then each damaged chunk's, named by file and chunk.
  std::vector<std::string> problems() const;

 private:
  // The save's finished chunk, or null (reported as generate() says). Its unknown cells are added to
  // `unknown` where given.
  std::unique_ptr<Chunk> read(ChunkPos pos, std::atomic<std::size_t>* unknown = nullptr) const;
  // A chunk's unblended tints, read once and kept; null where the save has no finished chunk.
  std::shared_ptr<const ColumnTints> columnTints(ChunkPos pos, const Chunk* read = nullptr) const;
  void blendTints(Chunk& chunk, std::shared_ptr<const ColumnTints> own) const;
  void report(std::string problem) const;
  std::unique_ptr<BlockStateMapper> takeMapper() const;
  void giveBack(std::unique_ptr<BlockStateMapper> mapper) const;

  MinecraftSave save_;
  const BlockRegistry& blocks_;
  BlockId placeholder_;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<BlockStateMapper>> mappers_;
  mutable std::vector<std::string> problems_;
  mutable std::atomic<std::size_t> unknownCells_ = 0;
  // Unblended tints of the chunks read, oldest first out past kKeptTints.
  static constexpr std::size_t kKeptTints = 4096;
  mutable std::map<ChunkPos, std::shared_ptr<const ColumnTints>> tints_;
  mutable std::deque<ChunkPos> tintOrder_;
};

}  // namespace terrasol
