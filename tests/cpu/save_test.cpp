#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <random>

#include "core/error.h"
#include "support/world_support.h"
#include "world/chunk_codec.h"
#include "world/chunk_streamer.h"
#include "world/generator.h"
#include "world/level.h"
#include "world/region_file.h"
#include "world/world_storage.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;
using testing::sameBlocks;
using testing::scratchDir;

std::vector<std::uint8_t> readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void writeBytes(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes,
                std::size_t count) {
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(count));
}

// A terrain chunk with random edits on top.
std::unique_ptr<Chunk> editedChunk(ChunkPos pos, unsigned seed) {
  static const auto gen = makeGenerator({"terrain", 5, {}}, defaultBlocks());
  auto chunk = std::make_unique<Chunk>(pos);
  gen->generate(*chunk);
  std::mt19937 rng(seed);
  for (int i = 0; i < 300; ++i) {
    chunk->set(static_cast<int>(rng() % 16), kMinY + static_cast<int>(rng() % (kMaxY - kMinY)),
               static_cast<int>(rng() % 16), static_cast<BlockId>(rng() % defaultBlocks().size()));
  }
  return chunk;
}

TEST(ChunkCodec, RoundTripsBlocksExactly) {
  const auto chunk = editedChunk({3, -4}, 1);
  // Cells holding water keep it: a waterlogged stair and seagrass.
  chunk->set(1, 70, 1, defaultBlocks().id("oak_stairs[waterlogged=true]"));
  chunk->set(2, 70, 1, defaultBlocks().id("seagrass"));
  const auto bytes = encodeChunk(*chunk, defaultBlocks());
  const auto back = decodeChunk({3, -4}, bytes.data(), bytes.size(), defaultBlocks());
  EXPECT_TRUE(sameBlocks(*chunk, *back));
  EXPECT_EQ(back->get(1, 70, 1), defaultBlocks().id("oak_stairs[waterlogged=true]"));
  EXPECT_LT(bytes.size(), 40000u) << "zstd should shrink a 200 KB chunk a lot";
}

// tests/saves/chunk_before_block_states.bin was written by the chunk codec as it was before blocks
// had states (commit 0a5e9cc^, built on its own): stone and grass floors, a row of oak_log, oak_log,
// oak_leaves, snow, glass, torch, glowstone, water, cobblestone and oak_planks at y 62, z 3, and a
// four-block log at (8, 62..65, 8). It opens with every block in place, the logs (a model block with
// an axis now) standing up, their default state, and its "snow" (the full block then) as
// snow_block; nothing is unknown.
TEST(ChunkCodec, ASaveFromBeforeBlockStatesOpens) {
  const BlockRegistry& b = defaultBlocks();
  const auto bytes = readBytes(std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "saves" /
                               "chunk_before_block_states.bin");
  ASSERT_FALSE(bytes.empty());
  std::vector<std::string> unknown;
  const auto chunk = decodeChunk({0, 0}, bytes.data(), bytes.size(), b, &unknown);
  EXPECT_TRUE(unknown.empty());
  EXPECT_EQ(chunk->get(5, 60, 5), b.id("stone"));
  EXPECT_EQ(chunk->get(5, 61, 5), b.id("grass_block"));
  const char* row[] = {
      "oak_log[axis=y]", "oak_log[axis=y]", "oak_leaves[distance=7,persistent=false,waterlogged=false]",
      "snow_block",      "glass",           "torch",
      "glowstone",       "water[level=0]",  "cobblestone",
      "oak_planks"};
  for (int i = 0; i < 10; ++i) EXPECT_EQ(b.stateName(chunk->get(i, 62, 3)), row[i]) << i;
  for (int y = 62; y < 66; ++y) EXPECT_EQ(chunk->get(8, y, 8), b.id("oak_log[axis=y]"));
  EXPECT_EQ(chunk->get(8, 66, 8), kAir);
}

TEST(ChunkCodec, GarbageIsAnErrorNotACrash) {
  const auto bytes = encodeChunk(*editedChunk({0, 0}, 2), defaultBlocks());
  for (std::size_t cut : {std::size_t{0}, std::size_t{3}, bytes.size() / 2, bytes.size() - 1}) {
    EXPECT_THROW(decodeChunk({0, 0}, bytes.data(), cut, defaultBlocks()), Error) << cut;
  }
  std::vector<std::uint8_t> noise(500);
  std::mt19937 rng(3);
  for (auto& b : noise) b = static_cast<std::uint8_t>(rng());
  EXPECT_THROW(decodeChunk({0, 0}, noise.data(), noise.size(), defaultBlocks()), Error);
}

TEST(RegionFile, SavesReloadAndTheNewestRecordWins) {
  const auto path = scratchDir("region_roundtrip") / "r.0.0.tsr";
  std::map<int, std::unique_ptr<Chunk>> saved;
  {
    RegionFile region(path, {0, 0});
    for (int i = 0; i < 12; ++i) {
      const ChunkPos p{i % 4, i % 3};
      saved[p.x * 100 + p.z] = editedChunk(p, static_cast<unsigned>(i));
      region.write(p, encodeChunk(*saved[p.x * 100 + p.z], defaultBlocks()));
    }
  }
  RegionFile region(path, {0, 0});
  EXPECT_TRUE(region.problems().empty());
  EXPECT_EQ(region.chunkCount(), saved.size());
  for (const auto& [key, chunk] : saved) {
    const auto bytes = region.read(chunk->pos());
    ASSERT_TRUE(bytes);
    EXPECT_TRUE(
        sameBlocks(*chunk, *decodeChunk(chunk->pos(), bytes->data(), bytes->size(), defaultBlocks())));
  }
  EXPECT_FALSE(region.read({31, 31}));
}

// Kill the process in the middle of the last save, at every byte: everything saved before stays
// readable, the interrupted chunk keeps its previous version, and the torn bytes are kept aside.
TEST(RegionFile, ASaveKilledAtAnyByteLosesNothingSavedBefore) {
  const auto dir = scratchDir("region_crash");
  const auto path = dir / "r.-1.0.tsr";
  const ChunkPos a{-1, 0}, b{-32, 31};
  // Payloads compared as bytes: the codec round trip is tested above, and this runs thousands of times.
  const auto payloadA = encodeChunk(*editedChunk(a, 10), defaultBlocks());
  const auto payloadB = encodeChunk(*editedChunk(b, 11), defaultBlocks());
  const auto payloadA2 = encodeChunk(*editedChunk(a, 12), defaultBlocks());
  std::size_t before = 0;
  {
    RegionFile region(path, {-1, 0});
    region.write(a, payloadA);
    region.write(b, payloadB);
    before = region.fileSize();
    region.write(a, payloadA2);  // the write that gets cut
  }
  const auto full = readBytes(path);
  ASSERT_GT(full.size(), before);
  for (std::size_t cut = before; cut <= full.size(); ++cut) {
    std::filesystem::remove_all(dir / "r.-1.0.tsr.corrupt");
    writeBytes(path, full, cut);
    RegionFile region(path, {-1, 0});
    ASSERT_EQ(region.read(b), payloadB) << "cut at " << cut;
    ASSERT_EQ(region.read(a), cut == full.size() ? payloadA2 : payloadA) << "cut at " << cut;
    if (cut == before || cut == full.size()) {
      EXPECT_TRUE(region.problems().empty()) << region.problems()[0];
      continue;
    }
    ASSERT_EQ(region.problems().size(), 1u) << "cut at " << cut;
    EXPECT_NE(region.problems()[0].find("torn record"), std::string::npos);
    if (cut - before >= 12) {  // the header got as far as the chunk coordinates
      EXPECT_NE(region.problems()[0].find("chunk (-1, 0)"), std::string::npos) << region.problems()[0];
    }
    const auto aside = dir / "r.-1.0.tsr.corrupt" /
                       ((cut - before >= 12 ? "chunk_-1_0" : "unknown_chunk") + std::string("_torn_at_") +
                        std::to_string(before) + ".bin");
    ASSERT_EQ(std::filesystem::file_size(aside), cut - before) << region.problems()[0];
    // The next save goes after the last good record and reads back.
    region.write(a, payloadA2);
    ASSERT_EQ(RegionFile(path, {-1, 0}).read(a), payloadA2) << "cut at " << cut;
  }
}

TEST(RegionFile, ACorruptChunkIsReportedKeptAsideAndTheRestLoads) {
  const auto dir = scratchDir("region_corrupt");
  const auto path = dir / "r.0.0.tsr";
  std::vector<std::unique_ptr<Chunk>> chunks;
  std::vector<std::uint64_t> offsets;
  {
    RegionFile region(path, {0, 0});
    for (int i = 0; i < 3; ++i) {
      chunks.push_back(editedChunk({i, 2 * i}, 20u + static_cast<unsigned>(i)));
      offsets.push_back(region.fileSize());
      region.write(chunks.back()->pos(), encodeChunk(*chunks.back(), defaultBlocks()));
    }
  }
  for (const std::size_t where : {std::size_t{40}, std::size_t{13}}) {  // a payload byte; the size field
    auto bytes = readBytes(path);
    const auto original = bytes;
    bytes[offsets[1] + where] ^= 0x5A;
    writeBytes(path, bytes, bytes.size());
    {
      RegionFile region(path, {0, 0});
      ASSERT_EQ(region.problems().size(), 1u);
      const std::string& problem = region.problems()[0];
      EXPECT_NE(problem.find(path.string()), std::string::npos) << problem;
      EXPECT_NE(problem.find(where == 13 ? "chunk (1, 2)" : "chunk (1, 2) fails its checksum"),
                std::string::npos)
          << problem;
      EXPECT_FALSE(region.read({1, 2}));
      EXPECT_TRUE(region.read({0, 0}));
      EXPECT_TRUE(region.read({2, 4})) << "the chunk after the corrupt one must still load";
      EXPECT_FALSE(std::filesystem::is_empty(dir / "r.0.0.tsr.corrupt"));
    }
    EXPECT_EQ(readBytes(path), bytes) << "opening must not rewrite the corrupt file";
    writeBytes(path, original, original.size());
    std::filesystem::remove_all(dir / "r.0.0.tsr.corrupt");
  }
}

TEST(RegionFile, CompactionKeepsOnlyTheNewestRecords) {
  const auto path = scratchDir("region_compact") / "r.0.0.tsr";
  RegionFile region(path, {0, 0});
  const auto chunk = editedChunk({1, 1}, 30);
  const auto payload = encodeChunk(*chunk, defaultBlocks());
  while (region.fileSize() < (1u << 20) + payload.size() * 2) region.write({1, 1}, payload);
  const auto other = editedChunk({2, 2}, 31);
  region.write({2, 2}, encodeChunk(*other, defaultBlocks()));
  EXPECT_TRUE(region.compactIfWasteful());
  EXPECT_LT(region.fileSize(), payload.size() * 3);
  RegionFile reopened(path, {0, 0});
  EXPECT_TRUE(reopened.problems().empty());
  const auto bytes = reopened.read({2, 2});
  ASSERT_TRUE(bytes);
  EXPECT_TRUE(sameBlocks(*other, *decodeChunk({2, 2}, bytes->data(), bytes->size(), defaultBlocks())));
}

TEST(Level, RoundTripsAndBadFilesNameTheKey) {
  const auto dir = scratchDir("level");
  Level level;
  level.seed = 123456789012345ull;
  level.time = 1'000'000'007;
  level.playerPosition = {29'999'000.5, 70.25, -12.75};
  level.playerYaw = 90.0f;
  level.playerFlying = true;
  level.props = {{"props/lamp.glb", {29'999'000.5, 64.0, -3.25}, {45.0f, 0.0f, 10.0f}, 0.5f}};
  saveLevel(dir / "level.json", level);
  const Level back = loadLevel(dir / "level.json");
  EXPECT_TRUE(back.playerFlying);
  ASSERT_EQ(back.props.size(), 1u);
  EXPECT_EQ(back.props[0].model, "props/lamp.glb");
  EXPECT_EQ(back.props[0].position, level.props[0].position);
  EXPECT_EQ(back.props[0].rotation, level.props[0].rotation);
  EXPECT_EQ(back.props[0].scale, 0.5f);
  EXPECT_EQ(back.seed, level.seed);
  EXPECT_EQ(back.time, level.time);
  EXPECT_EQ(back.playerPosition, level.playerPosition);
  EXPECT_EQ(back.playerYaw, 90.0f);

  auto error = [&](const std::string& text) {
    std::ofstream(dir / "bad.json") << text;
    try {
      loadLevel(dir / "bad.json");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{\"seed\": 1").find("bad.json:1:11: invalid JSON"), std::string::npos);
  EXPECT_NE(error(R"({"generator":"terrain","seed":1,"time":0})").find("bad.json: needs \"player\""),
            std::string::npos);
  EXPECT_NE(error(R"({"generator":"terrain","seed":"x","time":0})")
                .find("bad.json: seed: expected a whole number from 0 to 18446744073709551615, got \"x\""),
            std::string::npos);
  EXPECT_NE(
      error(R"({"generator":"terrain","seed":1,"time":0,"player":{"position":[1,2],"yaw":0,"pitch":0}})")
          .find("bad.json: player.position: expected an array of 3 numbers"),
      std::string::npos);
  const std::string player =
      R"("generator":"terrain","seed":1,"time":0,"player":{"position":[1,2,3],"yaw":0,"pitch":0})";
  EXPECT_NE(error("{" + player +
                  R"(,"props":[{"model":"a.glb","position":[0,0,0],"rotation":[0,0,0],"scale":-1}]})")
                .find("bad.json: props[0].scale: expected a number greater than 0 and at most 1000, got -1"),
            std::string::npos);
  EXPECT_NE(
      error("{" + player + R"(,"props":[{"position":[0,0,0]}]})").find("bad.json: props[0]: needs \"model\""),
      std::string::npos);
  EXPECT_NE(
      error("{" + player + R"(,"props":[{"model":"a","position":[0,"x",0],"rotation":[0,0,0],"scale":1}]})")
          .find("bad.json: props[0].position[1]: expected a number, got \"x\""),
      std::string::npos);
  EXPECT_EQ(error("{" + player + "}"), "no error") << "older files without props load";
  // level.json is Terrasol's own: an unknown key is a typo, named with its key path.
  const std::string root = R"({"version":1,"generator":"terrain","seed":1,"time":0,)";
  EXPECT_EQ(error(root + R"("player":{"position":[1,2,3],"yaw":0,"pitch":0,"flyng":true}})"),
            (dir / "bad.json").string() +
                ": player.flyng: unknown key; expected one of \"position\", \"yaw\", \"pitch\", \"flying\"");
  EXPECT_EQ(error("{" + player + R"(,"weather":"rain"})"),
            (dir / "bad.json").string() +
                ": weather: unknown key; expected one of \"version\", \"generator\", \"seed\", \"time\", "
                "\"player\", \"props\", \"minecraft\"");
  EXPECT_NE(error("{" + player +
                  R"(,"props":[{"model":"a","position":[0,0,0],"rotation":[0,0,0],"scale":1,"tint":2}]})")
                .find("bad.json: props[0].tint: unknown key"),
            std::string::npos);
}

// Random edits all over a 4 x 4 chunk area, saved through WorldStorage and read back into a new world.
TEST(WorldStorage, RandomEditsRoundTrip) {
  const BlockRegistry& blocks = defaultBlocks();
  const auto gen = makeGenerator({"terrain", 4, {}}, blocks);
  const auto dir = scratchDir("storage_roundtrip");
  std::map<std::pair<int, int>, std::unique_ptr<Chunk>> expected;
  std::mt19937 rng(99);
  {
    WorldStorage storage(dir, blocks);
    World world(blocks);
    for (int z = -2; z < 2; ++z)
      for (int x = -2; x < 2; ++x) {
        auto c = std::make_unique<Chunk>(ChunkPos{x, z});
        gen->generate(*c);
        world.insertChunk(std::move(c));
      }
    for (int i = 0; i < 5000; ++i) {
      const BlockPos p{static_cast<int>(rng() % 64) - 32, kMinY + static_cast<int>(rng() % 384),
                       static_cast<int>(rng() % 64) - 32};
      world.setBlock(p, static_cast<BlockId>(rng() % blocks.size()));
    }
    world.forEachChunk([&](const Chunk& c) {
      EXPECT_TRUE(c.modified());
      storage.save(c);
      expected[{c.pos().x, c.pos().z}] = std::make_unique<Chunk>(c.pos());
      for (int s = 0; s < kSectionCount; ++s) expected[{c.pos().x, c.pos().z}]->section(s) = c.section(s);
    });
    storage.flush();
  }
  WorldStorage storage(dir, blocks);
  for (const auto& [key, chunk] : expected) {
    const auto loaded = storage.load(chunk->pos());
    ASSERT_TRUE(loaded);
    EXPECT_TRUE(sameBlocks(*chunk, *loaded));
    EXPECT_FALSE(loaded->modified());
  }
  EXPECT_FALSE(storage.load({10, 10})) << "never saved: the generator makes it";
  EXPECT_TRUE(storage.problems().empty());
}

// The whole path: edit, walk away (the chunk is saved and unloaded), walk back (it loads from disk).
TEST(ChunkStreamer, EditedChunksSurviveUnloadingAndMemoryStaysBounded) {
  const BlockRegistry& blocks = defaultBlocks();
  const auto gen = makeGenerator({"terrain", 9, {}}, blocks);
  WorldStorage storage(scratchDir("streamer"), blocks);
  World world(blocks);
  ChunkStreamer streamer(world, *gen, &storage, 2, 2);
  auto settle = [&](ChunkPos center) {
    for (int i = 0; i < 10000 && (streamer.update(center), streamer.pending() > 0 || !world.isLoaded(center));
         ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    streamer.update(center);
  };
  settle({0, 0});
  EXPECT_EQ(world.chunkCount(), 25u);
  const BlockPos spot{5, 200, -7};
  ASSERT_TRUE(world.setBlock(spot, blocks.id("gold_block")));

  std::size_t most = 0;
  for (int x = 0; x <= 40; x += 4) {
    settle({x, 0});
    most = std::max(most, world.chunkCount());
  }
  EXPECT_FALSE(world.isLoaded(ChunkPos::of(spot)));
  EXPECT_LE(most, 7u * 7u) << "chunks beyond radius + 1 must be unloaded";

  settle({0, 0});
  EXPECT_EQ(world.getBlock(spot), blocks.id("gold_block"));
  EXPECT_TRUE(storage.problems().empty());
}

}  // namespace
}  // namespace terrasol
