// World benchmarks: terrain generation and save/load throughput.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "bench_support.h"
#include "core/paths.h"
#include "world/chunk_codec.h"
#include "world/generator.h"
#include "world/region_file.h"
#include "world/world_storage.h"

namespace terrasol {
namespace {

using bench::blocks;

// One 16 x 384 x 16 column of the terrain generator on one thread (goal: <= 2 ms). Positions walk
// across the world so caches and noise lattices are not reused between iterations.
void BM_TerrainColumn(benchmark::State& state) {
  const auto gen = makeGenerator({"terrain", 1, {}}, blocks());
  int i = 0;
  for (auto _ : state) {
    Chunk chunk({i * 7, i * 3 - 40});
    gen->generate(chunk);
    benchmark::DoNotOptimize(chunk);
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TerrainColumn)->Unit(benchmark::kMillisecond);

std::vector<std::unique_ptr<Chunk>> sampleChunks(int n) {
  const auto gen = makeGenerator({"terrain", 2, {}}, blocks());
  std::vector<std::unique_ptr<Chunk>> chunks;
  for (int i = 0; i < n; ++i) {
    chunks.push_back(std::make_unique<Chunk>(ChunkPos{i % 32, i / 32}));
    gen->generate(*chunks.back());
  }
  return chunks;
}

// Encode + compress + append to a region file (bytes = uncompressed chunk bytes saved per second).
void BM_SaveChunks(benchmark::State& state) {
  const auto chunks = sampleChunks(64);
  const auto dir = std::filesystem::temp_directory_path() / "terrasol-bench-save";
  std::filesystem::remove_all(dir);
  WorldStorage storage(dir, blocks());
  std::size_t saved = 0;
  for (auto _ : state) {
    for (const auto& c : chunks) storage.save(*c);
    saved += chunks.size();
  }
  storage.flush();
  state.SetItemsProcessed(static_cast<std::int64_t>(saved));
  double compressed = 0.0;
  for (const auto& c : chunks) compressed += static_cast<double>(encodeChunk(*c, blocks()).size());
  state.counters["compressed_bytes_per_chunk"] = compressed / static_cast<double>(chunks.size());
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_SaveChunks)->Unit(benchmark::kMillisecond);

// Read + verify checksum + decompress + decode, from a region written once.
void BM_LoadChunks(benchmark::State& state) {
  const auto chunks = sampleChunks(64);
  const auto dir = std::filesystem::temp_directory_path() / "terrasol-bench-load";
  std::filesystem::remove_all(dir);
  {
    WorldStorage storage(dir, blocks());
    for (const auto& c : chunks) storage.save(*c);
  }
  WorldStorage storage(dir, blocks());
  std::size_t loaded = 0;
  for (auto _ : state) {
    for (const auto& c : chunks) benchmark::DoNotOptimize(storage.load(c->pos()));
    loaded += chunks.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(loaded));
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_LoadChunks)->Unit(benchmark::kMillisecond);

// Opening a region file scans and checksums every record: the cost of the crash-safe format.
void BM_OpenRegion(benchmark::State& state) {
  const auto chunks = sampleChunks(256);
  const auto dir = std::filesystem::temp_directory_path() / "terrasol-bench-open";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    RegionFile region(dir / "r.0.0.tsr", {0, 0});
    for (const auto& c : chunks) region.write(c->pos(), encodeChunk(*c, blocks()));
  }
  for (auto _ : state) {
    RegionFile region(dir / "r.0.0.tsr", {0, 0});
    benchmark::DoNotOptimize(region.chunkCount());
  }
  state.counters["chunks"] = static_cast<double>(chunks.size());
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_OpenRegion)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace terrasol

BENCHMARK_MAIN();
