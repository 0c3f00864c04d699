#include "minecraft/minecraft_source.h"

#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>

#include "core/error.h"

namespace terrasol {
namespace {

BlockId placeholderOf(const BlockRegistry& blocks) {
  bool found = false;
  const BlockId id = blocks.find("unknown_block", &found);
  if (!found) throw Error("the block registry has no unknown_block to stand in for blocks nothing knows");
  return id;
}

void copyTints(const Chunk& from, Chunk& to) {
  for (int z = 0; z < kChunkSize; ++z)
    for (int x = 0; x < kChunkSize; ++x) to.setTint(x, z, from.tint(x, z));
}

}  // namespace

MinecraftChunkSource::MinecraftChunkSource(const std::filesystem::path& dir, const BlockRegistry& blocks)
    : save_(dir), blocks_(blocks), placeholder_(placeholderOf(blocks)), problems_(save_.problems()) {}

std::unique_ptr<BlockStateMapper> MinecraftChunkSource::takeMapper() const {
  const std::lock_guard lock(mutex_);
  if (mappers_.empty()) return std::make_unique<BlockStateMapper>(blocks_, placeholder_);
  std::unique_ptr<BlockStateMapper> mapper = std::move(mappers_.back());
  mappers_.pop_back();
  return mapper;
}

void MinecraftChunkSource::giveBack(std::unique_ptr<BlockStateMapper> mapper) const {
  const std::lock_guard lock(mutex_);
  mappers_.push_back(std::move(mapper));
}

std::unique_ptr<Chunk> MinecraftChunkSource::read(ChunkPos pos) const {
  if (!save_.contains(pos)) return nullptr;
  std::unique_ptr<BlockStateMapper> mapper = takeMapper();
  std::unique_ptr<Chunk> chunk;
  try {
    std::optional<AnvilChunk> read = save_.load(pos, *mapper);
    if (read && read->full) {
      unknownCells_ += read->unknownCells;
      chunk = std::move(read->chunk);
    }
  } catch (const Error& e) {
    const std::lock_guard lock(mutex_);
    problems_.push_back(std::string(e.what()) + "; chunk left out");
  }
  giveBack(std::move(mapper));
  return chunk;
}

void MinecraftChunkSource::generate(Chunk& chunk) const {
  const std::unique_ptr<Chunk> read = this->read(chunk.pos());
  if (!read) return;
  for (int s = 0; s < kSectionCount; ++s) chunk.section(s) = std::move(read->section(s));
  copyTints(*read, chunk);
}

void MinecraftChunkSource::fillTints(Chunk& chunk) const {
  if (const std::unique_ptr<Chunk> read = this->read(chunk.pos())) copyTints(*read, chunk);
}

int MinecraftChunkSource::surfaceHeight(int x, int z) const {
  Chunk chunk(ChunkPos::of({x, 0, z}));
  generate(chunk);
  return chunk.highestBlock(x & kLastCell, z & kLastCell);
}

glm::dvec3 MinecraftChunkSource::startPosition() const {
  if (save_.level().player) return *save_.level().player;
  const auto standOn = [&](int x, int z) {
    return glm::dvec3(x + 0.5, std::max(surfaceHeight(x, z) + 1, kMinY), z + 0.5);
  };
  if (save_.level().spawn) return standOn(save_.level().spawn->x, save_.level().spawn->z);
  // A bare region folder: the middle of the chunks it holds.
  const std::vector<ChunkPos> chunks = save_.chunks();
  if (chunks.empty()) return {0.0, 80.0, 0.0};
  glm::dvec2 sum(0.0);
  for (const ChunkPos c : chunks) sum += glm::dvec2(c.x, c.z);
  const glm::dvec2 mid = sum / static_cast<double>(chunks.size());
  const ChunkPos nearest = *std::min_element(chunks.begin(), chunks.end(), [&](ChunkPos a, ChunkPos b) {
    const auto d = [&](ChunkPos c) { return std::hypot(c.x - mid.x, c.z - mid.y); };
    return d(a) < d(b);
  });
  return standOn(nearest.x * kChunkSize + 8, nearest.z * kChunkSize + 8);
}

std::vector<std::string> MinecraftChunkSource::problems() const {
  const std::lock_guard lock(mutex_);
  return problems_;
}

}  // namespace terrasol
