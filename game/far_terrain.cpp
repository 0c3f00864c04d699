#include "far_terrain.h"

#include <cmath>

#include "lod/chunk_tiles.h"
#include "lod/generator_tiles.h"

namespace terrasol {

std::unique_ptr<FarTerrain> FarTerrain::create(const LodSettings& settings, const PlayWorld& world,
                                               LodPalette palette) {
  if (settings.distance <= 0 || !lodCanSample(world.streamed().generator())) return nullptr;
  return std::unique_ptr<FarTerrain>(new FarTerrain(settings, world, std::move(palette)));
}

FarTerrain::FarTerrain(const LodSettings& settings, const PlayWorld& world, LodPalette palette)
    : generator_(world.streamed().generator()),
      blocks_(world.world().blocks()),
      settings_(settings),
      terrain_([this](LodTileKey key) { return tile(key); }, std::move(palette),
               LodLevels{settings.minLevel, settings.detail}, 1) {}

LodTile FarTerrain::tile(LodTileKey key) const {
  return tileFromSource(generator_, key, blocks_, [&](int x, int z) -> std::optional<LodColumn> {
    std::lock_guard lock(editsMutex_);
    if (const auto it = edited_.find({x, z}); it != edited_.end()) return it->second;
    return std::nullopt;
  });
}

void FarTerrain::update(glm::dvec3 camera, int viewDistance, const PlayWorld& world, LodMeshes& meshes) {
  // Edits since the last frame: their columns as the world now has them, then their tiles again.
  const std::vector<Edit>& edits = world.edits();
  for (; editsSeen_ < edits.size(); ++editsSeen_) {
    const BlockPos& at = edits[editsSeen_].pos;
    const ChunkPos pos = ChunkPos::of(at);
    const Chunk* chunk = world.world().chunk(pos);
    if (!chunk) continue;
    const LodColumn column = chunkColumn(*chunk, at.x - pos.minBlockX(), at.z - pos.minBlockZ(), blocks_);
    {
      std::lock_guard lock(editsMutex_);
      edited_[{at.x, at.z}] = column;
    }
    terrain_.invalidate(at.x, at.z);
  }

  const glm::ivec2 centre(static_cast<int>(std::floor(camera.x / kChunkSize)),
                          static_cast<int>(std::floor(camera.z / kChunkSize)));
  const int radius = viewDistance + 1;
  const int size = 2 * radius + 1;
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(size * size));
  for (int z = 0; z < size; ++z)
    for (int x = 0; x < size; ++x)
      mask[static_cast<std::size_t>(z * size + x)] =
          world.streamed().meshable({centre.x - radius + x, centre.y - radius + z}) ? 1 : 0;
  if (mask != mask_ || centre - radius != maskOrigin_) {
    meshes.setFullDetail(centre - radius, size, mask);
    mask_ = std::move(mask);
    maskOrigin_ = centre - radius;
  }

  LodView view;
  view.camera = {camera.x, camera.z};
  view.distance = static_cast<double>(settings_.distance) * kChunkSize;
  view.reach = ChunkSquare{centre - radius, centre + radius};
  // Chunks the streamer keeps meshed all round the player; while they load, the tiles under them show.
  view.covered = ChunkSquare{centre - (viewDistance - 1), centre + (viewDistance - 1)};
  terrain_.update(view);
  if (std::optional<LodSet> set = terrain_.takeSet()) meshes.show(*set);
}

}  // namespace terrasol
