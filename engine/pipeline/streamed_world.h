#pragma once
// A streamed world (the game's, and a saved world the exporter reads): a save directory, the chunks streamed
// around the player (generated or loaded on worker threads), their light, and remeshing on worker threads.
// Each frame the game hands it the player's chunk and a time budget; it returns finished meshes. Plain C++:
// tests play it with no GL.

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <unordered_set>
#include <vector>

#include "light/light_engine.h"
#include "mesh/mesh_scheduler.h"
#include "minecraft/minecraft_source.h"
#include "world/chunk_streamer.h"
#include "world/level.h"
#include "world/world_storage.h"

namespace terrasol {

struct WorldCounts {
  std::size_t loaded = 0, pending = 0, meshable = 0, meshDirty = 0, meshInFlight = 0;
};

class StreamedWorld {
 public:
  // Opens DIR (level.json and the saved chunks) or creates it with `seed` (a new world's seed; an
  // existing world keeps its own). Throws Error naming the file when level.json is malformed.
  // `shapes` (World's): collision, targeting and light through shaped blocks; it must outlive this.
  // `minecraftSave`: a new world overlays that Minecraft save (Level::minecraft); an existing world
  // keeps what its level.json says. Throws Error as MinecraftSave does for a save it cannot read.
  StreamedWorld(const std::filesystem::path& dir, std::uint64_t seed, const BlockRegistry& blocks,
                const BlockMeshTable& table, int viewDistance, int threads,
                const BlockShapes* shapes = nullptr, const std::filesystem::path& minecraftSave = {});
  ~StreamedWorld();

  bool isNew() const { return isNew_; }
  // The Minecraft save under this world, or null for Terrasol's own worlds.
  const MinecraftChunkSource* minecraft() const { return minecraft_; }
  Level& level() { return level_; }
  const Level& level() const { return level_; }
  World& world() { return world_; }
  const World& world() const { return world_; }
  const LightEngine& light() const { return light_; }
  const ChunkGenerator& generator() const { return *generator_; }
  // Whether the chunk is meshed (all its neighbours are loaded): drawn in full detail.
  bool meshable(ChunkPos pos) const { return meshable_.contains(pos); }

  // Streams chunks around `centre` (adding and lighting them until `deadline`, at least one a frame),
  // queues dirty sections for meshing and returns the meshes finished since the last call (an empty
  // mesh removes its section; unloaded chunks come back as empty meshes).
  std::vector<SectionMesh> update(ChunkPos centre, std::chrono::steady_clock::time_point deadline);

  // An edit by the player: the block, its light, and the meshes of what changed.
  std::optional<BlockChange> setBlock(const BlockPos& pos, BlockId id);

  // Chunks within this many of the player are drawn; one more ring is loaded for their borders.
  void setViewDistance(int chunks);
  // A new mesher table (packs reloaded): every meshed section is meshed again with it.
  void remeshAll(const BlockMeshTable& table);

  // The highest block a player can stand on at (x, z), when its chunk is loaded.
  std::optional<int> surfaceY(int x, int z) const;

  // Saves every edited chunk and level.json (time and player are the caller's to put in level()).
  void save();
  const std::filesystem::path& dir() const { return storage_.dir(); }

  WorldCounts counts() const;

 private:
  bool allNeighboursLoaded(ChunkPos pos) const;
  void chunkAdded(ChunkPos pos);
  void chunkRemoved(ChunkPos pos);
  void markChunkDirty(ChunkPos pos);

  bool isNew_;
  Level level_;
  World world_;
  WorldStorage storage_;
  std::unique_ptr<ChunkGenerator> generator_;
  const MinecraftChunkSource* minecraft_ = nullptr;  // generator_, when it is a save
  LightEngine light_;
  int threads_;
  std::unique_ptr<MeshScheduler> mesher_;
  // Chunks whose eight neighbours are loaded: only they are meshed (their borders are known).
  std::unordered_set<ChunkPos> meshable_;
  std::vector<SectionMesh> removed_;  // empty meshes for sections of chunks that stopped being meshable
  ChunkStreamer streamer_;            // last: its loader threads stop first
};

}  // namespace terrasol
