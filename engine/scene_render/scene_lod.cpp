#include "scene_render/scene_lod.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "lod/generator_tiles.h"

namespace terrasol {
namespace {

// How far round the camera's own square the mask looks for chunks drawn for other frames' cameras.
constexpr int kMaskMargin = 2;

}  // namespace

std::unique_ptr<SceneLod> SceneLod::create(const LodSettings& settings, const SceneWorld& world,
                                           LodPalette palette) {
  if (settings.distance <= 0 || !lodCanSample(world.generator())) return nullptr;
  return std::unique_ptr<SceneLod>(new SceneLod(settings, world, std::move(palette)));
}

SceneLod::SceneLod(const LodSettings& settings, const SceneWorld& world, LodPalette palette)
    : world_(world),
      settings_(settings),
      terrain_([&source = world.generator(), &blocks = world.world().blocks()](
                   LodTileKey key) { return tileFromSource(source, key, blocks); },
               std::move(palette), LodLevels{settings.minLevel, settings.detail},
               static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))) {}

void SceneLod::update(glm::dvec3 camera, LodMeshes& meshes) {
  const auto start = std::chrono::steady_clock::now();
  const glm::ivec2 centre(static_cast<int>(std::floor(camera.x / kChunkSize)),
                          static_cast<int>(std::floor(camera.z / kChunkSize)));
  const int view = world_.viewDistance();
  const int radius = view + kMaskMargin;
  const int size = 2 * radius + 1;
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(size * size));
  for (int z = 0; z < size; ++z)
    for (int x = 0; x < size; ++x)
      covered[static_cast<std::size_t>(z * size + x)] =
          world_.shown({centre.x - radius + x, centre.y - radius + z}) ? 1 : 0;
  meshes.setFullDetail(centre - radius, size, covered);

  LodView v;
  v.camera = {camera.x, camera.z};
  v.distance = static_cast<double>(settings_.distance) * kChunkSize;
  v.reach = ChunkSquare{centre - radius, centre + radius};
  v.covered = ChunkSquare{centre - view, centre + view};
  terrain_.update(v, true);
  if (std::optional<LodSet> set = terrain_.takeSet()) meshes.show(*set);
  longestMs_ =
      std::max(longestMs_,
               std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace terrasol
