// Minecraft save benchmarks: a chunk read from its region (in the page cache), inflated, parsed and
// decoded into a Terrasol chunk, on one thread. Needs the test data's go-mc 1.18.1 save
// ($TERRASOL_TESTDATA/worlds/go-mc-1.18.1); skipped without it.

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "core/paths.h"
#include "minecraft/minecraft_save.h"

namespace terrasol {
namespace {

// Goal: >= 2 000 chunks a second (items_per_second).
void BM_MinecraftChunkDecode(benchmark::State& state) {
  const std::optional<std::filesystem::path> data = testDataDir();
  if (!data) {
    state.SkipWithError("no test data ($TERRASOL_TESTDATA/worlds/go-mc-1.18.1)");
    return;
  }
  const MinecraftSave save(*data / "worlds" / "go-mc-1.18.1");
  const std::vector<ChunkPos> chunks = save.chunks();
  BlockStateMapper mapper(bench::blocks(), kAir);
  std::size_t i = 0;
  for (auto _ : state) {
    std::optional<AnvilChunk> c = save.load(chunks[i++ % chunks.size()], mapper);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MinecraftChunkDecode)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace terrasol
