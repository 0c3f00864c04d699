// terrasol-export: a world region's meshed blocks as a glTF 2.0 binary (.glb) with the atlas textures.
//   terrasol-export WORLD_DIR|SCENE.json --region x0,y0,z0,x1,y1,z1 --out region.glb [--pack PATH]...
// A world directory is read as saved (edited chunks) and generated (the rest), never written; a
// Minecraft save directory (no level.json) is read as a scene's world, never written either; a scene
// is built with its edits. Bad arguments or input: the reason on stderr and exit status 1.

#include <charconv>
#include <chrono>
#include <cstdio>
#include <thread>

#include "core/error.h"
#include "core/paths.h"
#include "core/tool_main.h"
#include "minecraft/minecraft_save.h"
#include "pipeline/streamed_world.h"
#include "region_export.h"
#include "scene/scene_world.h"

namespace terrasol {
namespace {

Region parseRegion(const std::string& text) {
  int v[6];
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 6; ++i) {
    const auto [next, ec] = std::from_chars(p, end, v[i]);
    if (ec != std::errc() || (i < 5 ? next == end || *next != ',' : next != end)) {
      throw Error("--region: expected x0,y0,z0,x1,y1,z1 in whole blocks, got '" + text + "'");
    }
    p = next + 1;
  }
  Region r{{std::min(v[0], v[3]), std::min(v[1], v[4]), std::min(v[2], v[5])},
           {std::max(v[0], v[3]), std::max(v[1], v[4]), std::max(v[2], v[5])}};
  const glm::ivec3 size = r.max - r.min + 1;
  if (size.x > 1024 || size.z > 1024) throw Error("--region: at most 1024 blocks across, got " + text);
  return r;
}

int run(int argc, char** argv) {
  std::filesystem::path input, out;
  std::optional<Region> region;
  std::vector<std::filesystem::path> extraPacks;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(arg + ": missing value");
      return argv[++i];
    };
    if (arg == "--region")
      region = parseRegion(value());
    else if (arg == "--out")
      out = value();
    else if (arg == "--pack")
      extraPacks.emplace_back(value());
    else if (input.empty() && !arg.starts_with("--"))
      input = arg;
    else
      throw Error("unknown argument '" + arg + "'");
  }
  if (input.empty() || !region || out.empty()) {
    throw Error(
        "usage: terrasol-export WORLD_DIR|SCENE.json --region x0,y0,z0,x1,y1,z1 --out region.glb [--pack "
        "PATH]...");
  }
  const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  const glm::ivec3 centre = (region->min + region->max) / 2;
  const int radius = (std::max(region->max.x - region->min.x, region->max.z - region->min.z) + 1) / 32 + 1;

  PackStack packs;
  std::vector<std::filesystem::path> packPaths;
  std::optional<SceneFile> scene;
  if (!std::filesystem::is_directory(input)) {
    scene = loadScene(input);
    packPaths = scene->packs;
  } else if (!std::filesystem::exists(input / "level.json")) {
    // A Minecraft save (read-only, as a scene's world); anything else is named as no world.
    try {
      MinecraftSave check(input);
    } catch (const Error& e) {
      throw Error(input.string() + ": not a world (no level.json) nor a Minecraft save (" + e.what() + ")");
    }
    scene.emplace();
    scene->minecraftWorld = input;
    packPaths.push_back(resourcePackDir() / "default");
  } else {
    packPaths.push_back(resourcePackDir() / "default");
  }
  for (const auto& p : extraPacks) packPaths.push_back(p);
  for (const auto& p : packPaths) packs.push(ResourcePack::open(p));
  BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  const BlockMeshTable table = meshTableOf(blocks, atlas);

  std::vector<SectionMesh> meshes;
  if (scene) {
    scene->cameraPosition = glm::dvec3(centre) + 0.5;
    scene->viewDistance = radius;
    const SceneWorld world(*scene, blocks);
    meshes = meshRegion(world.world(), *region, table);
  } else {
    const BlockShapes shapes = defaultPackShapes(blocks);
    StreamedWorld world(input, 0, blocks, table, radius, 2, &shapes);
    const ChunkPos chunk = ChunkPos::of({centre.x, 0, centre.z});
    for (int i = 0; i < 100000; ++i) {
      world.update(chunk, std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
      const WorldCounts c = world.counts();
      if (c.loaded > 0 && c.pending == 0) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    meshes = meshRegion(world.world(), *region, table);
  }
  const ExportStats stats = exportRegion(meshes, *region, atlas, out);
  std::printf("terrasol-export: %zu quads (%zu vertices, %zu triangles) from %zu sections written to %s\n",
              stats.quads, stats.vertices, stats.triangles, meshes.size(), out.string().c_str());
  return 0;
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-export", [&] { return terrasol::run(argc, argv); });
}
