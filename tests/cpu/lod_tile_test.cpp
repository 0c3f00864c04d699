// Far terrain's tiles (lod/): a cell's summary of hand-built columns, the generator sampled coarsely
// against the chunks it makes, and a save's chunks read whole.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "lod/chunk_tiles.h"
#include "lod/generator_tiles.h"
#include "lod/lod_summary.h"
#include "minecraft/minecraft_save.h"
#include "minecraft/minecraft_source.h"
#include "support/test_data.h"
#include "support/world_support.h"
#include "world/chunk.h"
#include "world/terrain_generator.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

TEST(LodSummary, TheHighestColumnGivesTheTopAndWaterNeedsMostColumns) {
  const BlockRegistry& b = defaultBlocks();
  const BlockId grass = b.id("grass_block"), stone = b.id("stone"), sand = b.id("sand"),
                water = b.id("water");
  // A ridge of stone beside grass: the cell keeps the ridge's height and the grass most columns show.
  const std::vector<LodColumn> ridge = {{70, grass}, {75, stone}, {71, grass}, {69, grass}};
  const LodCell top = summarizeColumns(ridge);
  EXPECT_EQ(top.top, 75);
  EXPECT_EQ(top.surface, grass);
  EXPECT_EQ(top.water, kNoLodHeight);
  // Two and two: the higher pair's block.
  EXPECT_EQ(
      summarizeColumns(std::vector<LodColumn>{{70, grass}, {75, stone}, {74, stone}, {69, grass}}).surface,
      stone);
  // A coast: three of four columns under the sea, the fourth a beach above it.
  const std::vector<LodColumn> coast = {
      {55, sand, 62, water}, {58, sand, 62, water}, {60, sand, 62, water}, {63, sand}};
  const LodCell sea = summarizeColumns(coast);
  EXPECT_EQ(sea.top, 63);
  EXPECT_EQ(sea.water, 62);
  EXPECT_EQ(sea.waterBlock, water);
  // A pond in one column of four does not flood the cell.
  const std::vector<LodColumn> pond = {{64, grass}, {64, grass}, {60, sand, 63, water}, {64, grass}};
  EXPECT_EQ(summarizeColumns(pond).water, kNoLodHeight);
  EXPECT_EQ(summarizeColumns({}), LodCell{}) << "no columns: an empty cell";
}

// The highest block of a column that is ground (not air, water, ice, a plant, a tree or snow on it)
// and, with `crowns`, the highest that is ground or a tree's leaves.
int groundTop(const Chunk& chunk, int x, int z, const BlockRegistry& b, bool crowns) {
  for (int y = kMaxY - 1; y >= kMinY; --y) {
    const BlockId id = chunk.get(x, y, z);
    if (id == kAir) continue;
    const std::string& name = b[id].name;
    const bool leaves = name.find("leaves") != std::string::npos;
    const bool ground = (b[id].isOpaqueCube() || (crowns && leaves)) &&
                        name.find("log") == std::string::npos && (crowns || !leaves) && name != "ice";
    if (ground) return y;
  }
  return kNoLodHeight;
}

// Cells of 8 blocks sampled at 16 of their 64 columns, against the chunks the generator makes there
// (caves and trees included): every cell's top within one cell of their highest ground, or above it
// under a crown; within one cell of their highest ground or leaves but where a crown's edge reaches
// in only between the sampled columns. Seed 24's first tile holds a coast, hills and forest, seed 3's
// mountains to y 208.
int cellsUnderWater(std::uint64_t seed) {
  const BlockRegistry& b = defaultBlocks();
  const TerrainGenerator generator(seed, b);
  const LodTileKey key{3, 0, 0};
  const LodTile tile = tileFromGenerator(generator, key);
  const int cell = key.cellBlocks(), chunks = 6;  // the tile's first 96 x 96 blocks
  const int cellsPerSide = chunks * kChunkSize / cell;
  const auto cells = static_cast<std::size_t>(cellsPerSide * cellsPerSide);
  std::vector<int> ground(cells, kNoLodHeight), crowns(cells, kNoLodHeight);
  for (int cz = 0; cz < chunks; ++cz)
    for (int cx = 0; cx < chunks; ++cx) {
      Chunk chunk({cx, cz});
      generator.generate(chunk);
      for (int z = 0; z < kChunkSize; ++z)
        for (int x = 0; x < kChunkSize; ++x) {
          const int bx = cx * kChunkSize + x, bz = cz * kChunkSize + z;
          const auto i = static_cast<std::size_t>((bz / cell) * cellsPerSide + bx / cell);
          ground[i] = std::max(ground[i], groundTop(chunk, x, z, b, false));
          crowns[i] = std::max(crowns[i], groundTop(chunk, x, z, b, true));
        }
    }
  std::size_t onGround = 0, withCrowns = 0, wet = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    const LodCell& c =
        tile.cells[static_cast<std::size_t>((i / cellsPerSide) * kLodTileCells + i % cellsPerSide)];
    onGround += c.top >= ground[i] - cell && c.top <= std::max(ground[i] + cell, crowns[i]) ? 1 : 0;
    withCrowns += std::abs(c.top - crowns[i]) <= cell ? 1 : 0;
    wet += c.water > c.top ? 1 : 0;
  }
  std::printf(
      "seed %llu: of %zu cells, %zu within a cell of the ground (or under a crown), %zu within a cell "
      "of the ground and crowns, %zu under water\n",
      static_cast<unsigned long long>(seed), cells, onGround, withCrowns, wet);
  EXPECT_EQ(onGround, cells) << "seed " << seed;
  EXPECT_GE(withCrowns * 100, cells * 98) << "seed " << seed;
  return static_cast<int>(wet);
}

TEST(GeneratorTiles, CoarseSamplesAgreeWithTheChunksWithinACell) {
  EXPECT_GT(cellsUnderWater(24), 10) << "a coast";
  cellsUnderWater(3);
}

// The column rule is generate()'s own: where no cave or plant took it, the generator's chunk holds the
// column's top block at its height, and water over it up to the sea.
TEST(GeneratorTiles, TheColumnRuleIsTheGenerators) {
  const BlockRegistry& b = defaultBlocks();
  const TerrainGenerator generator(1, b);
  int same = 0, columns = 0;
  for (int cz = -2; cz < 2; ++cz)
    for (int cx = -2; cx < 2; ++cx) {
      Chunk chunk({cx, cz});
      generator.generate(chunk);
      for (int z = 0; z < kChunkSize; ++z)
        for (int x = 0; x < kChunkSize; ++x) {
          const SurfaceColumn c = *generator.surfaceColumn(cx * kChunkSize + x, cz * kChunkSize + z);
          ++columns;
          same += chunk.get(x, c.height, z) == c.top &&
                          (c.water == kNoLodHeight || chunk.get(x, c.water, z) == c.waterBlock)
                      ? 1
                      : 0;
        }
    }
  std::printf("%d of %d columns hold the rule's top block\n", same, columns);
  EXPECT_GE(same, columns * 97 / 100);
}

// Hand-built chunks, one column a cell (level 0): a pool, a tree's leaves, a flower, and a chunk that is
// not there.
TEST(ChunkTiles, ColumnsKeepTheirGroundWaterAndLeavesAndMissingChunksLeaveCellsEmpty) {
  const BlockRegistry& b = defaultBlocks();
  const auto flat = makeGenerator({"flat", 0, {}}, b);
  std::map<std::pair<int, int>, std::unique_ptr<Chunk>> chunks;
  for (const auto& [x, z] : {std::pair{0, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
    auto chunk = std::make_unique<Chunk>(ChunkPos{x, z});
    flat->generate(*chunk);
    chunks[{x, z}] = std::move(chunk);
  }
  Chunk& home = *chunks[{0, 0}];
  home.set(2, 63, 3, b.id("water"));
  home.set(2, 62, 3, b.id("sand"));
  home.set(5, 70, 5, b.id("oak_leaves"));
  home.set(7, 64, 7, b.id("poppy"));
  const LodTile tile = tileFromChunks(
      {0, 0, 0},
      [&](ChunkPos p) -> const Chunk* {
        const auto found = chunks.find({p.x, p.z});
        return found == chunks.end() ? nullptr : found->second.get();
      },
      b);
  EXPECT_EQ(tile.at(0, 0), (LodCell{63, b.id("grass_block")}));
  EXPECT_EQ(tile.at(2, 3), (LodCell{62, b.id("sand"), 63, b.id("water")}));
  EXPECT_EQ(tile.at(5, 5), (LodCell{70, b.id("oak_leaves")}));
  EXPECT_EQ(tile.at(7, 7).top, 63) << "a flower is too small to show from afar";
  EXPECT_EQ(tile.at(20, 4), LodCell{}) << "chunk (1, 0) is not there";
  EXPECT_EQ(tile.at(20, 20).top, 63);
}

// A source that holds a few finished chunks of a flat world, one with a pillar, and counts what it makes.
class HeldChunks : public ChunkGenerator {
 public:
  explicit HeldChunks(const BlockRegistry& b)
      : flat_(makeGenerator({"flat", 0, {}}, b)), stone_(b.id("stone")) {}
  void generate(Chunk& chunk) const override {
    ++made;
    flat_->generate(chunk);
    if (chunk.pos() == ChunkPos{1, 0}) chunk.set(3, 90, 4, stone_);
  }
  int surfaceHeight(int x, int z) const override { return flat_->surfaceHeight(x, z); }
  bool holdsChunks() const override { return true; }
  bool holdsChunk(ChunkPos pos) const override { return pos.z == 0 && (pos.x == 0 || pos.x == 1); }
  mutable int made = 0;

 private:
  std::unique_ptr<ChunkGenerator> flat_;
  BlockId stone_;
};

// With no column rule, a tile comes from the chunks the source holds, each made once however many
// columns are sampled in it, the same as from those chunks made beforehand; the rest stays empty.
TEST(ChunkTiles, ASourceOfHeldChunksMakesEachOnceAndLeavesTheRestEmpty) {
  const BlockRegistry& b = defaultBlocks();
  const HeldChunks source(b);
  EXPECT_TRUE(lodCanSample(source));
  const LodTileKey key{1, 0, 0};  // cells of 2 blocks: 64 columns sampled in each chunk
  const LodTile tile = tileFromSource(source, key, b);
  EXPECT_EQ(source.made, 2);
  std::map<std::pair<int, int>, std::unique_ptr<Chunk>> chunks;
  for (const int x : {0, 1}) {
    chunks[{x, 0}] = std::make_unique<Chunk>(ChunkPos{x, 0});
    source.generate(*chunks[{x, 0}]);
  }
  const LodTile expected = tileFromChunks(
      key,
      [&](ChunkPos p) -> const Chunk* {
        const auto found = chunks.find({p.x, p.z});
        return found == chunks.end() ? nullptr : found->second.get();
      },
      b);
  EXPECT_TRUE(tile.cells == expected.cells);
  EXPECT_EQ(tile.at(9, 2).top, 90) << "the pillar at (19, 4)";
  EXPECT_EQ(tile.at(20, 2), LodCell{}) << "chunk (2, 0) is not held";
  EXPECT_EQ(tile.at(3, 12), LodCell{}) << "chunk (0, 1) is not held";
  // The player's edits come first.
  const LodTile edited = tileFromSource(source, key, b, [](int x, int z) -> std::optional<LodColumn> {
    if (x / 2 == 20 && z / 2 == 2) return LodColumn{100, 1};
    return std::nullopt;
  });
  EXPECT_EQ(edited.at(20, 2).top, 100);
  EXPECT_FALSE(lodCanSample(*makeGenerator({"flat", 0, {}}, b))) << "no rule, no chunks of its own";
}

// A real Minecraft save (go-mc 1.18.1, 593 chunks), its chunks loaded beforehand and read on demand
// through the source that opens it (the same cells): every cell of 4 blocks over its chunks has ground,
// never above the highest block the save's columns hold, and its top or water no lower than that
// block by more than a cell (what lies above the ground and water is plants, snow and torches).
TEST(ChunkTiles, AMinecraftSavesTilesFollowItsSurface) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const BlockRegistry& b = defaultBlocks();
  const MinecraftSave save(testing::testData() / "worlds" / "go-mc-1.18.1");
  const MinecraftChunkSource source(testing::testData() / "worlds" / "go-mc-1.18.1", b);
  BlockStateMapper mapper(b, kAir);
  std::map<std::pair<int, int>, std::unique_ptr<Chunk>> chunks;
  for (const ChunkPos pos : save.chunks()) {
    if (auto c = save.load(pos, mapper)) chunks[{pos.x, pos.z}] = std::move(c->chunk);
  }
  ASSERT_EQ(chunks.size(), 593u);
  const ChunkLookup lookup = [&](ChunkPos p) -> const Chunk* {
    const auto found = chunks.find({p.x, p.z});
    return found == chunks.end() ? nullptr : found->second.get();
  };
  // The highest block of any kind over a cell's columns.
  const auto highestBlock = [&](int x0, int z0, int cell) {
    int highest = kNoLodHeight;
    for (int z = z0; z < z0 + cell; ++z)
      for (int x = x0; x < x0 + cell; ++x) {
        const ChunkPos pos = ChunkPos::of(BlockPos{x, 0, z});
        const Chunk& c = *lookup(pos);
        for (int y = kMaxY - 1; y > highest; --y)
          if (c.get(x - pos.minBlockX(), y, z - pos.minBlockZ()) != kAir) highest = y;
      }
    return highest;
  };
  const LodTileKey probe{2, 0, 0};
  int cells = 0, near = 0, wet = 0;
  std::map<std::pair<int, int>, bool> tiles;
  const auto tileOf = [&](int chunk) {  // floor division
    const int blocks = chunk * kChunkSize, span = probe.spanBlocks();
    return blocks >= 0 ? blocks / span : -((-blocks + span - 1) / span);
  };
  for (const auto& [at, chunk] : chunks) tiles[{tileOf(at.first), tileOf(at.second)}] = true;
  for (const auto& [t, unused] : tiles) {
    const LodTileKey key{2, t.first, t.second};
    const LodTile tile = tileFromChunks(key, lookup, b);
    // The save as the game and scenes open it: the same ground, water and blocks, read on demand.
    const LodTile held = tileFromSource(source, key, b);
    for (int cz = 0; cz < kLodTileCells; ++cz)
      for (int cx = 0; cx < kLodTileCells; ++cx) {
        const LodCell &a = tile.at(cx, cz), &h = held.at(cx, cz);
        ASSERT_TRUE(a.top == h.top && a.surface == h.surface && a.water == h.water &&
                    a.waterBlock == h.waterBlock)
            << "cell " << cx << ", " << cz << " of tile " << key.x << ", " << key.z;
        const int x0 = key.minBlockX() + cx * key.cellBlocks(), z0 = key.minBlockZ() + cz * key.cellBlocks();
        if (!lookup(ChunkPos::of(BlockPos{x0, 0, z0}))) {
          EXPECT_EQ(tile.at(cx, cz), LodCell{});
          continue;
        }
        const LodCell& c = tile.at(cx, cz);
        const int highest = highestBlock(x0, z0, key.cellBlocks());
        ++cells;
        ASSERT_NE(c.top, kNoLodHeight);
        ASSERT_LE(std::max(c.top, c.water), highest);
        near += std::max(c.top, c.water) >= highest - key.cellBlocks() ? 1 : 0;
        wet += c.water > c.top ? 1 : 0;
      }
  }
  std::printf("%d cells of 4 blocks: %d within a cell of the save's highest block, %d under water\n", cells,
              near, wet);
  EXPECT_EQ(cells, 593 * 16);
  EXPECT_GE(near, cells * 98 / 100);
}

}  // namespace
}  // namespace terrasol
