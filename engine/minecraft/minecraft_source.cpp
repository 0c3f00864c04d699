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

void MinecraftChunkSource::report(std::string problem) const {
  const std::lock_guard lock(mutex_);
  // A damaged neighbour is read for its tints before its own turn: said once.
  if (std::find(problems_.begin(), problems_.end(), problem) == problems_.end())
    problems_.push_back(std::move(problem));
}

std::unique_ptr<Chunk> MinecraftChunkSource::read(ChunkPos pos, std::atomic<std::size_t>* unknown) const {
  if (!save_.contains(pos)) return nullptr;
  std::unique_ptr<BlockStateMapper> mapper = takeMapper();
  std::unique_ptr<Chunk> chunk;
  try {
    std::optional<AnvilChunk> read = save_.load(pos, *mapper);
    if (read && read->full) {
      if (unknown) *unknown += read->unknownCells;
      chunk = std::move(read->chunk);
    }
  } catch (const Error& e) {
    report(std::string(e.what()) + "; chunk left out");
  }
  giveBack(std::move(mapper));
  return chunk;
}

std::shared_ptr<const ColumnTints> MinecraftChunkSource::columnTints(ChunkPos pos, const Chunk* read) const {
  {
    const std::lock_guard lock(mutex_);
    if (const auto found = tints_.find(pos); found != tints_.end()) return found->second;
  }
  std::unique_ptr<Chunk> fresh;
  if (!read) read = (fresh = this->read(pos)).get();
  std::shared_ptr<const ColumnTints> tints;
  if (read) tints = std::make_shared<const ColumnTints>(columnTintsOf(*read));
  const std::lock_guard lock(mutex_);
  if (tints_.emplace(pos, tints).second) {
    tintOrder_.push_back(pos);
    if (tintOrder_.size() > kKeptTints) {
      tints_.erase(tintOrder_.front());
      tintOrder_.pop_front();
    }
  }
  return tints;
}

void MinecraftChunkSource::blendTints(Chunk& chunk, std::shared_ptr<const ColumnTints> own) const {
  std::array<std::shared_ptr<const ColumnTints>, 9> held;
  std::array<const ColumnTints*, 9> around{};
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx) {
      const auto i = static_cast<std::size_t>((dz + 1) * 3 + dx + 1);
      held[i] = dx == 0 && dz == 0 ? own : columnTints({chunk.pos().x + dx, chunk.pos().z + dz});
      around[i] = held[i].get();
    }
  blendBiomeTints(around, chunk);
}

void MinecraftChunkSource::generate(Chunk& chunk) const {
  const std::unique_ptr<Chunk> read = this->read(chunk.pos(), &unknownCells_);
  if (!read) return;
  for (int s = 0; s < kSectionCount; ++s) chunk.section(s) = std::move(read->section(s));
  blendTints(chunk, columnTints(chunk.pos(), read.get()));
}

void MinecraftChunkSource::fillTints(Chunk& chunk) const {
  if (std::shared_ptr<const ColumnTints> own = columnTints(chunk.pos())) blendTints(chunk, std::move(own));
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
