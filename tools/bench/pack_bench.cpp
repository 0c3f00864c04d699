// Resource pack benchmarks: loading the block textures and building the three atlases with mipmaps.

#include <benchmark/benchmark.h>

#include <optional>

#include "assets/atlas.h"
#include "core/paths.h"
#include "scene/block_atlas.h"
#include "world/block_registry.h"

namespace terrasol {
namespace {

// The texture names the game asks for with `packs`: every block face's and every model's.
std::vector<std::vector<std::string>> blockTextureNames(const PackStack& packs) {
  const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  return atlasTextureNames(blocks, bakeBlockModels(blocks, packs));
}

// With `withPixelPerfection`, the third-party test data's pack on top (null when that is absent).
std::optional<PackStack> stack(bool withPixelPerfection) {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  if (withPixelPerfection) {
    const auto data = testDataDir();
    if (!data) return std::nullopt;
    packs.push(ResourcePack::open(*data / "packs" / "pixel_perfection_ce"));
  }
  return packs;
}

std::vector<LoadedTexture> load(const PackStack& packs, const std::vector<std::vector<std::string>>& names) {
  std::vector<PackProblem> problems;
  std::vector<LoadedTexture> textures;
  for (const auto& candidates : names) textures.push_back(loadBlockTexture(packs, candidates, problems));
  return textures;
}

// Decoding every block texture and its companions (arg 1: pixel_perfection_ce over the default pack).
void BM_PackLoadTextures(benchmark::State& state) {
  const auto packs = stack(state.range(0) == 1);
  if (!packs) return state.SkipWithError("no third-party test data (TERRASOL_TESTDATA)");
  const auto names = blockTextureNames(*packs);
  for (auto _ : state) benchmark::DoNotOptimize(load(*packs, names));
}
BENCHMARK(BM_PackLoadTextures)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Laying out and building the albedo, normal and specular atlases with all mip levels.
void BM_AtlasBuild(benchmark::State& state) {
  const auto packs = stack(state.range(0) == 1);
  if (!packs) return state.SkipWithError("no third-party test data (TERRASOL_TESTDATA)");
  const auto textures = load(*packs, blockTextureNames(*packs));
  Atlas atlas;
  for (auto _ : state) benchmark::DoNotOptimize(atlas = buildAtlas(textures));
  state.counters["tiles"] = atlas.columns * atlas.rows;
  state.counters["tile_size"] = atlas.tileSize;
  state.counters["atlas_side"] = atlas.albedo[0].width;
}
BENCHMARK(BM_AtlasBuild)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace terrasol
