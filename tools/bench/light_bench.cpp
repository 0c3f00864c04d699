// Light benchmarks, single thread. Each reports microseconds per operation and block_reads_per_set:
// block ids looked up per light value written (Starlight's figure of merit: about one).

#include <benchmark/benchmark.h>

#include <chrono>

#include "bench_support.h"
#include "core/paths.h"
#include "light/light_engine.h"
#include "world/generator.h"

namespace terrasol {
namespace {

using bench::blocks;

// 5 x 5 lit chunks around the origin.
struct Scene : bench::LitArea {
  explicit Scene(const std::string& generator) : LitArea(generator, 2) {}
};

void report(benchmark::State& state, const LightStats& stats) {
  state.counters["block_reads_per_set"] =
      stats.lightWrites ? static_cast<double>(stats.blockReads) / static_cast<double>(stats.lightWrites)
                        : 0.0;
  state.counters["sets_per_op"] =
      benchmark::Counter(static_cast<double>(stats.lightWrites), benchmark::Counter::kAvgIterations);
}

// Times only `op`; `undo` restores the scene between iterations, untimed.
template <class Op, class Undo>
void timed(benchmark::State& state, Scene& scene, Op op, Undo undo) {
  LightStats total;
  for (auto _ : state) {
    scene.light.resetStats();
    const auto start = std::chrono::steady_clock::now();
    op();
    const auto end = std::chrono::steady_clock::now();
    state.SetIterationTime(std::chrono::duration<double>(end - start).count());
    total.blockReads += scene.light.stats().blockReads;
    total.lightWrites += scene.light.stats().lightWrites;
    undo();
    scene.light.takeChangedSections();
  }
  report(state, total);
}

// A torch on a grass plain (flat world, surface y = 63).
void BM_LightTorchPlace(benchmark::State& state) {
  Scene scene("flat");
  const BlockId torch = blocks().id("torch");
  timed(
      state, scene,
      [&] {
        scene.set({8, 64, 8}, torch);
      },
      [&] {
        scene.set({8, 64, 8}, kAir);
      });
}
BENCHMARK(BM_LightTorchPlace)->UseManualTime()->Unit(benchmark::kMicrosecond);

void BM_LightTorchRemove(benchmark::State& state) {
  Scene scene("flat");
  const BlockId torch = blocks().id("torch");
  scene.set({8, 64, 8}, torch);
  timed(
      state, scene,
      [&] {
        scene.set({8, 64, 8}, kAir);
      },
      [&] {
        scene.set({8, 64, 8}, torch);
      });
}
BENCHMARK(BM_LightTorchRemove)->UseManualTime()->Unit(benchmark::kMicrosecond);

// Glowstone floating in the air: a full diamond of radius 15 in every direction.
void BM_LightGlowstoneOpenAir(benchmark::State& state) {
  Scene scene("void");
  const BlockId glowstone = blocks().id("glowstone");
  timed(
      state, scene,
      [&] {
        scene.set({8, 100, 8}, glowstone);
      },
      [&] {
        scene.set({8, 100, 8}, kAir);
      });
}
BENCHMARK(BM_LightGlowstoneOpenAir)->UseManualTime()->Unit(benchmark::kMicrosecond);

// Relighting from scratch the section of a terrain chunk that holds the ground surface. Its light is
// cleared before each run (untimed), so every level must be found and written again.
void BM_LightFullRelight(benchmark::State& state) {
  Scene scene("terrain");
  const int surface = scene.gen->surfaceHeight(8, 8);
  const SectionPos section{0, sectionOf(surface), 0};
  ChunkLight& light = scene.world.chunk({0, 0})->light();
  auto clear = [&] {
    light.block[static_cast<std::size_t>(section.section)].fill(0);
    light.sky[static_cast<std::size_t>(section.section)].fill(0);
  };
  clear();
  timed(
      state, scene, [&] { scene.light.relightSection(section); }, clear);
  state.counters["surface_y"] = surface;
}
BENCHMARK(BM_LightFullRelight)->UseManualTime()->Unit(benchmark::kMicrosecond);

// The same section relit while its light is right: every level is found again, nothing is written.
void BM_LightRelightUnchanged(benchmark::State& state) {
  Scene scene("terrain");
  const SectionPos section{0, sectionOf(scene.gen->surfaceHeight(8, 8)), 0};
  timed(
      state, scene, [&] { scene.light.relightSection(section); }, [] {});
}
BENCHMARK(BM_LightRelightUnchanged)->UseManualTime()->Unit(benchmark::kMicrosecond);

// Lighting a whole terrain chunk as it loads, next to lit neighbours.
void BM_LightChunkLoad(benchmark::State& state) {
  Scene scene("terrain");
  timed(
      state, scene,
      [&] {
        scene.light.chunkLoaded({0, 0});
      },
      [&] {
        scene.light.chunkUnloading({0, 0});
      });
}
BENCHMARK(BM_LightChunkLoad)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace terrasol

namespace terrasol {
namespace {
// The fixed cost of an update: a torch sealed in stone lights only its own cell.
void BM_LightSealedTorch(benchmark::State& state) {
  Scene scene("flat");
  const BlockId torch = blocks().id("torch");
  scene.set({8, 40, 8}, kAir);
  timed(
      state, scene,
      [&] {
        scene.set({8, 40, 8}, torch);
      },
      [&] {
        scene.set({8, 40, 8}, kAir);
      });
}
BENCHMARK(BM_LightSealedTorch)->UseManualTime()->Unit(benchmark::kMicrosecond);
}  // namespace
}  // namespace terrasol
