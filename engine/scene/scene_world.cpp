#include "scene/scene_world.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "core/error.h"
#include "mesh/mesh_scheduler.h"
#include "mesh/section_mesh.h"
#include "minecraft/minecraft_source.h"
#include "scene/block_atlas.h"
#include "scene/camera_path.h"
#include "world/connected_states.h"

namespace terrasol {
namespace {

// The chunk of every frame's camera, each once.
std::vector<ChunkPos> cameraChunks(const SceneFile& scene) {
  // Clamped so a camera far outside the world border still names a valid chunk.
  const double limit = 30'000'000.0;
  const auto block = [&](double v) { return static_cast<int>(std::floor(std::clamp(v, -limit, limit))); };
  std::vector<ChunkPos> chunks;
  for (int frame = 0; frame < scene.frameCount(); ++frame) {
    const glm::dvec3 p = cameraAtFrame(scene, frame).position;
    chunks.push_back(ChunkPos::of({block(p.x), 0, block(p.z)}));
  }
  std::sort(chunks.begin(), chunks.end());
  chunks.erase(std::unique(chunks.begin(), chunks.end()), chunks.end());
  return chunks;
}

// The chunks within `radius` of any of `centres`, each once, row by row (z, then x).
std::vector<ChunkPos> chunksAround(const std::vector<ChunkPos>& centres, int radius) {
  std::vector<ChunkPos> chunks;
  for (const ChunkPos& c : centres)
    for (int dz = -radius; dz <= radius; ++dz)
      for (int dx = -radius; dx <= radius; ++dx) chunks.push_back({c.x + dx, c.z + dz});
  const auto rowOrder = [](ChunkPos a, ChunkPos b) { return a.z != b.z ? a.z < b.z : a.x < b.x; };
  std::sort(chunks.begin(), chunks.end(), rowOrder);
  chunks.erase(std::unique(chunks.begin(), chunks.end()), chunks.end());
  return chunks;
}

}  // namespace

SceneWorld::SceneWorld(const SceneFile& scene, const BlockRegistry& blocks)
    : SceneWorld(scene, blocks, defaultPackShapes(blocks)) {}

SceneWorld::SceneWorld(const SceneFile& scene, const BlockRegistry& blocks, BlockShapes shapes)
    : shapes_(std::move(shapes)),
      world_(blocks, &shapes_),
      light_(world_),
      centres_(cameraChunks(scene)),
      viewDistance_(scene.viewDistance),
      loaded_(chunksAround(centres_, viewDistance_ + 1)) {
  const bool minecraft = !scene.minecraftWorld.empty();
  try {
    generator_ = minecraft ? std::make_unique<MinecraftChunkSource>(scene.minecraftWorld, blocks)
                           : makeGenerator({scene.generator, scene.seed, {}}, blocks);
  } catch (const Error& e) {
    throw Error(sceneError(scene, minecraft ? "world.minecraft" : "world.generator", e.what()));
  }
  for (const ChunkPos& pos : loaded_) {
    auto chunk = std::make_unique<Chunk>(pos);
    generator_->generate(*chunk);
    world_.insertChunk(std::move(chunk));
  }
  for (const SceneEdit& edit : scene.edits) {
    bool found = false;
    std::string problem;
    const BlockId block = blocks.find(edit.block, &found, &problem);
    if (!found) throw Error(sceneError(scene, edit.key + ".block", problem));
    const bool now = edit.atFrame < 0;
    if (now) forEachCell(edit, [&](const BlockPos& p) { world_.setBlock(p, block); });
    edits_.push_back({edit, block, now});
  }
  // Stairs beside each other turn into corners, as placed ones do.
  for (const Edit& e : edits_) {
    if (!e.applied) continue;
    forEachCell(e.edit, [&](const BlockPos& p) {
      for (const auto& [at, state] : connectionUpdates(world_, p)) world_.setBlock(at, state);
    });
  }
  // Light after the edits: one propagation instead of one per edited block.
  for (const ChunkPos& pos : loaded_) light_.chunkLoaded(pos);
  light_.takeChangedSections();  // everything is meshed fresh anyway
}

// Only the part of the box inside the loaded chunks and the world's height is visited, chunk by
// chunk, so a huge box costs no more than the loaded area.
template <class F>
void SceneWorld::forEachCell(const SceneEdit& edit, F&& f) const {
  for (const ChunkPos& c : loaded_) {
    const glm::ivec3 lo(std::max(edit.from.x, c.minBlockX()), std::max(edit.from.y, kMinY),
                        std::max(edit.from.z, c.minBlockZ()));
    const glm::ivec3 hi(std::min(edit.to.x, c.minBlockX() + kLastCell), std::min(edit.to.y, kMaxY - 1),
                        std::min(edit.to.z, c.minBlockZ() + kLastCell));
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) f(BlockPos{x, y, z});
  }
}

bool SceneWorld::withinView(SectionPos pos) const {
  return std::any_of(centres_.begin(), centres_.end(), [&](ChunkPos c) {
    return std::abs(pos.x - c.x) <= viewDistance_ && std::abs(pos.z - c.z) <= viewDistance_;
  });
}

std::vector<SectionMesh> SceneWorld::advanceTo(int frame, const BlockMeshTable& table) {
  MeshScheduler scheduler(table, 1);
  bool changed = false;
  for (Edit& e : edits_) {
    if (e.applied || e.edit.atFrame > frame) continue;
    e.applied = true;
    const auto set = [&](const BlockPos& p, BlockId block) {
      if (const auto change = world_.setBlock(p, block)) {
        light_.blockChanged(*change);
        scheduler.markBlockChanged(p);
        changed = true;
      }
    };
    forEachCell(e.edit, [&](const BlockPos& p) { set(p, e.block); });
    forEachCell(e.edit, [&](const BlockPos& p) {
      for (const auto& [at, state] : connectionUpdates(world_, p)) set(at, state);
    });
  }
  std::vector<SectionMesh> meshes;
  if (!changed) return meshes;
  for (const SectionPos& s : light_.takeChangedSections()) scheduler.markDirty(s);
  // Drained to the end: every change is in the frame it belongs to.
  while (scheduler.dirty() > 0 || scheduler.inFlight() > 0) {
    for (SectionMesh& mesh : scheduler.update(world_)) {
      if (withinView(mesh.pos)) meshes.push_back(std::move(mesh));
    }
    // A picture with a section left out would be wrong: no frame is rendered without it.
    if (const auto failed = scheduler.takeFailures(); !failed.empty()) throw Error(failed.front().message());
    std::this_thread::yield();
  }
  return meshes;
}

std::vector<SectionMesh> SceneWorld::meshVisible(const BlockMeshTable& table) const {
  std::vector<SectionMesh> meshes;
  SectionSnapshot snapshot;
  for (const ChunkPos& c : chunksAround(centres_, viewDistance_))
    for (int s = 0; s < kSectionCount; ++s) {
      SectionMesh mesh = meshFromWorld(world_, {c.x, s, c.z}, table, snapshot);
      // Kept even when empty: a closed section's links still hide what lies behind it.
      if (!mesh.empty() || mesh.faceLinks != kAllFacesLinked) meshes.push_back(std::move(mesh));
    }
  return meshes;
}

}  // namespace terrasol
