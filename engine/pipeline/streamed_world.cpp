#include "pipeline/streamed_world.h"

#include <algorithm>

#include "core/log.h"

namespace terrasol {
namespace {

constexpr std::size_t kSnapshotsPerFrame = 96;

Level openLevel(const std::filesystem::path& dir, std::uint64_t seed, const std::filesystem::path& minecraft,
                bool& isNew) {
  const std::filesystem::path file = dir / "level.json";
  isNew = !std::filesystem::exists(file);
  if (!isNew) return loadLevel(file);
  Level level;
  level.seed = seed;
  level.time = 1000;  // morning, as Minecraft starts
  if (!minecraft.empty()) {
    level.generator = "minecraft";
    level.minecraft = std::filesystem::absolute(minecraft).lexically_normal();
  }
  return level;
}

std::unique_ptr<ChunkGenerator> sourceOf(const Level& level, const BlockRegistry& blocks) {
  if (!level.minecraft.empty()) return std::make_unique<MinecraftChunkSource>(level.minecraft, blocks);
  return makeGenerator({level.generator, level.seed, {}}, blocks);
}

}  // namespace

StreamedWorld::StreamedWorld(const std::filesystem::path& dir, std::uint64_t seed,
                             const BlockRegistry& blocks, const BlockMeshTable& table, int viewDistance,
                             int threads, const BlockShapes* shapes,
                             const std::filesystem::path& minecraftSave)
    : level_(openLevel(dir, seed, minecraftSave, isNew_)),
      world_(blocks, shapes),
      storage_(dir, blocks),
      generator_(sourceOf(level_, blocks)),
      minecraft_(dynamic_cast<const MinecraftChunkSource*>(generator_.get())),
      light_(world_),
      threads_(threads),
      mesher_(std::make_unique<MeshScheduler>(table, threads)),
      streamer_(world_, *generator_, &storage_, threads, viewDistance + 1) {
  streamer_.setHooks([this](ChunkPos p) { chunkAdded(p); }, [this](ChunkPos p) { chunkRemoved(p); });
  if (isNew_) saveLevel(storage_.levelFile(), level_);  // the directory is a world from now on
}

StreamedWorld::~StreamedWorld() = default;

bool StreamedWorld::allNeighboursLoaded(ChunkPos pos) const {
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx)
      if (!world_.isLoaded({pos.x + dx, pos.z + dz})) return false;
  return true;
}

void StreamedWorld::markChunkDirty(ChunkPos pos) {
  for (int s = 0; s < kSectionCount; ++s) mesher_->markDirty({pos.x, s, pos.z});
}

void StreamedWorld::chunkAdded(ChunkPos pos) {
  light_.chunkLoaded(pos);
  // The chunk and each neighbour become meshable once all their neighbours are here.
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx) {
      const ChunkPos c{pos.x + dx, pos.z + dz};
      if (!meshable_.contains(c) && world_.isLoaded(c) && allNeighboursLoaded(c)) {
        meshable_.insert(c);
        markChunkDirty(c);
      }
    }
}

void StreamedWorld::chunkRemoved(ChunkPos pos) {
  light_.chunkUnloading(pos);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dx = -1; dx <= 1; ++dx) {
      const ChunkPos c{pos.x + dx, pos.z + dz};
      if (!meshable_.erase(c)) continue;
      for (int s = 0; s < kSectionCount; ++s) removed_.push_back(SectionMesh{{c.x, s, c.z}, {}});
    }
}

std::vector<SectionMesh> StreamedWorld::update(ChunkPos centre,
                                               std::chrono::steady_clock::time_point deadline) {
  streamer_.update(centre, [&] { return std::chrono::steady_clock::now() < deadline; });
  for (const SectionPos& s : light_.takeChangedSections()) {
    if (meshable_.contains({s.x, s.z})) mesher_->markDirty(s);
  }
  std::vector<SectionMesh> out = std::move(removed_);
  removed_.clear();
  for (SectionMesh& mesh : mesher_->update(world_, kSnapshotsPerFrame)) {
    // A job that finished after its chunk left must not bring the chunk back.
    if (meshable_.contains({mesh.pos.x, mesh.pos.z})) out.push_back(std::move(mesh));
  }
  // A mesh is drawn from the world, which stays whole: the game goes on (and saves) with the
  // section's old mesh, and the log names the section and the cause.
  for (const MeshFailure& failure : mesher_->takeFailures()) logError(failure.message());
  return out;
}

std::optional<BlockChange> StreamedWorld::setBlock(const BlockPos& pos, BlockId id) {
  std::optional<BlockChange> change = world_.setBlock(pos, id);
  if (!change) return change;
  light_.blockChanged(*change);
  mesher_->markBlockChanged(pos);
  return change;
}

void StreamedWorld::setViewDistance(int chunks) {
  streamer_.setRadius(chunks + 1);
}

void StreamedWorld::remeshAll(const BlockMeshTable& table) {
  mesher_.reset();  // joins its workers before the old table goes
  mesher_ = std::make_unique<MeshScheduler>(table, threads_);
  for (ChunkPos c : meshable_) markChunkDirty(c);
}

std::optional<int> StreamedWorld::surfaceY(int x, int z) const {
  if (!world_.isLoaded(ChunkPos::of({x, 0, z}))) return std::nullopt;
  for (int y = kMaxY - 1; y >= kMinY; --y) {
    const BlockType& type = world_.blocks()[world_.getBlock({x, y, z})];
    if (type.shape == BlockShape::Cube || type.shape == BlockShape::Liquid) return y;
  }
  return kMinY;
}

void StreamedWorld::save() {
  streamer_.saveAll();
  saveLevel(storage_.levelFile(), level_);
}

WorldCounts StreamedWorld::counts() const {
  return {world_.chunkCount(), streamer_.pending(), meshable_.size(), mesher_->dirty(), mesher_->inFlight()};
}

}  // namespace terrasol
