// Meshing benchmarks, single thread, per section: taking the snapshot plus meshing it. Counters:
// ns_per_quad (time / quads produced) and bytes_per_vertex.

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "core/paths.h"
#include "light/light_engine.h"
#include "mesh/mesher.h"
#include "mesh/section_visibility.h"
#include "scene/block_atlas.h"
#include "world/connected_states.h"
#include "world/generator.h"
#include "world/terrain_generator.h"

namespace terrasol {
namespace {

using bench::blocks;

// The default pack's shapes and atlas, as the game meshes with them (logs are model blocks drawn as
// cubes; a pane's quads come from its models).
const BlockShapes& shapes() {
  static const BlockShapes s = defaultPackShapes(blocks());
  return s;
}
const BlockAtlas& atlas() {
  static const BlockAtlas a = [] {
    PackStack packs;
    packs.push(ResourcePack::open(resourcePackDir() / "default"));
    return buildBlockAtlas(blocks(), packs);
  }();
  return a;
}

// A lit 3 x 3 chunk terrain world around the origin.
struct Terrain : bench::LitArea {
  Terrain() : LitArea("terrain", 1, &shapes()), table(meshTableOf(blocks(), atlas())) {}
  BlockMeshTable table;
};

void meshBenchmark(benchmark::State& state, Terrain& t, SectionPos section, CaptureResult expected) {
  SectionSnapshot snapshot;
  std::size_t quads = 0;
  for (auto _ : state) {
    const CaptureResult r = captureSection(t.world, section, snapshot);
    if (r != expected) {
      state.SkipWithError("the section is not the kind this benchmark wants");
      return;
    }
    if (r == CaptureResult::Captured) {
      const SectionMesh mesh = meshSection(snapshot, t.table);
      quads = mesh.quads();
      benchmark::DoNotOptimize(mesh);
    }
  }
  state.counters["quads"] = static_cast<double>(quads);
  if (quads > 0) {
    state.counters["ns_per_quad"] =
        benchmark::Counter(static_cast<double>(quads) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  }
  state.counters["bytes_per_vertex"] = sizeof(PackedVertex);
}

// A section packed with shaped blocks, drawn through their models: rows of stairs (turning into
// corners where they meet), fences and glass panes joined to each other, eight layers high, an empty
// row between each three.
void BM_MeshShapes(benchmark::State& state) {
  struct Shaped : bench::LitArea {
    Shaped() : LitArea("void", 1, &shapes()), table(meshTableOf(blocks(), atlas())) {}
    BlockMeshTable table;
  } s;
  const char* rows[] = {"oak_stairs[facing=north]", "oak_fence", "glass_pane"};
  for (int y = 64; y < 72; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x) {
        if (z % 4 != 3) s.set({x, y, z}, blocks().id(rows[z % 4]));
      }
  for (int y = 64; y < 72; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x) {
        const BlockPos p{x, y, z};
        s.set(p, connectedState(s.world, p, s.world.getBlock(p)));
      }
  SectionSnapshot snapshot;
  std::size_t quads = 0;
  for (auto _ : state) {
    captureSection(s.world, {0, sectionOf(64), 0}, snapshot);
    const SectionMesh mesh = meshSection(snapshot, s.table);
    quads = mesh.quads();
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["quads"] = static_cast<double>(quads);
  state.counters["ns_per_quad"] =
      benchmark::Counter(static_cast<double>(quads) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MeshShapes)->Unit(benchmark::kMicrosecond);

// The section holding the ground at the centre of a chunk, on land.
void BM_MeshSurface(benchmark::State& state) {
  Terrain t;
  meshBenchmark(state, t, {0, sectionOf(t.gen->surfaceHeight(8, 8)), 0}, CaptureResult::Captured);
}
BENCHMARK(BM_MeshSurface)->Unit(benchmark::kMicrosecond);

// The most cave-riddled underground section of the centre chunk (the most faces).
void BM_MeshCave(benchmark::State& state) {
  Terrain t;
  int best = 0;
  std::size_t most = 0;
  for (int s = 1; s < sectionOf(t.gen->surfaceHeight(8, 8)) - 1; ++s) {
    SectionSnapshot snapshot;
    if (captureSection(t.world, {0, s, 0}, snapshot) != CaptureResult::Captured) continue;
    const std::size_t quads = meshSection(snapshot, t.table).quads();
    if (quads > most) most = quads, best = s;
  }
  meshBenchmark(state, t, {0, best, 0}, CaptureResult::Captured);
}
BENCHMARK(BM_MeshCave)->Unit(benchmark::kMicrosecond);

// Cave culling's face links of the surface section (computed on the mesh workers beside the mesh).
void BM_SectionFaceLinks(benchmark::State& state) {
  Terrain t;
  SectionSnapshot snapshot;
  if (captureSection(t.world, {0, sectionOf(t.gen->surfaceHeight(8, 8)), 0}, snapshot) !=
      CaptureResult::Captured) {
    state.SkipWithError("the surface section has nothing to mesh");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(sectionFaceLinks(snapshot));
}
BENCHMARK(BM_SectionFaceLinks)->Unit(benchmark::kMicrosecond);

void BM_MeshEmpty(benchmark::State& state) {
  Terrain t;
  meshBenchmark(state, t, {0, kSectionCount - 1, 0}, CaptureResult::Empty);
}
BENCHMARK(BM_MeshEmpty)->Unit(benchmark::kMicrosecond);

// Solid stone with stone all around (a flat world's deep layers).
void BM_MeshBuried(benchmark::State& state) {
  Terrain t;
  const auto flat = makeGenerator({"flat", 0, parseFlatLayers("bedrock,100*stone", blocks())}, blocks());
  for (int z = -1; z <= 1; ++z)
    for (int x = -1; x <= 1; ++x) {
      auto c = std::make_unique<Chunk>(ChunkPos{x + 10, z});
      flat->generate(*c);
      t.world.insertChunk(std::move(c));
    }
  meshBenchmark(state, t, {10, sectionOf(48), 0}, CaptureResult::Buried);
}
BENCHMARK(BM_MeshBuried)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace terrasol
