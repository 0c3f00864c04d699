// Minecraft saves, read-only: worlds of each format era written by the tests' own writer and read back
// block for block, every kind of damage reported by file and chunk, and the real saves in the test
// data (skipped without it).

#include "minecraft/minecraft_save.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/error.h"
#include "minecraft/chunk_compression.h"
#include "support/anvil_writer.h"
#include "support/test_data.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

using namespace testing;

constexpr int kV1_13_2 = 1631, kV1_16 = 2566, kV1_18_1 = 2865, kV1_20_6 = 3839;

// A fresh folder per test.
std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("terrasol_mc_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A section with a pattern that needs five bits: 17 states laid out by a formula of the cell.
TestSection patterned(int y) {
  TestSection s;
  s.y = y;
  s.palette = {"air",
               "stone",
               "dirt",
               "oak_log[axis=x]",
               "oak_log[axis=z]",
               "glass",
               "sand",
               "gravel",
               "oak_planks",
               "cobblestone",
               "bricks",
               "oak_slab[type=top,waterlogged=true]",
               "torch",
               "glowstone",
               "short_grass",
               "oak_stairs[facing=north,half=top,shape=straight,waterlogged=false]",
               "water[level=0]"};
  s.indices.resize(4096);
  for (int i = 0; i < 4096; ++i)
    s.indices[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>((i * 7 + i / 97) % 17);
  return s;
}

BlockId expectedAt(const TestSection& s, int i) {
  const std::string& state = s.palette[s.indices[static_cast<std::size_t>(i)]];
  return state == "air" ? kAir : defaultBlocks().id(state);
}

void expectSection(const Chunk& chunk, const TestSection& s) {
  for (int i = 0; i < 4096; ++i) {
    const int x = i & 15, z = (i >> 4) & 15, y = s.y * 16 + (i >> 8);
    ASSERT_EQ(chunk.get(x, y, z), expectedAt(s, i)) << "cell " << i << " of section " << s.y;
  }
}

AnvilChunk loadOne(const std::filesystem::path& dir, ChunkPos pos) {
  const MinecraftSave save(dir);
  BlockStateMapper mapper(defaultBlocks(), kAir);
  std::optional<AnvilChunk> c = save.load(pos, mapper);
  EXPECT_TRUE(c.has_value());
  return std::move(*c);
}

// Each era's layout read back block for block: 1.13's spanning longs, 1.16's unspanned ones, 1.18's
// sections with a one-entry palette and no data, below y = 0 too.
TEST(MinecraftSave, EachFormatEraReadsBackBlockForBlock) {
  for (const int version : {kV1_13_2, kV1_16, kV1_18_1, kV1_20_6}) {
    SCOPED_TRACE(version);
    const auto dir = scratch("era" + std::to_string(version));
    const TestSection mixed = patterned(3);
    TestSection solid{.y = version >= kV1_18_1 ? -2 : 1, .palette = {"deepslate"}, .indices = {}};
    const ChunkPos pos{-3, 5};
    writeRegion(dir / "region", {{pos, encodeNbt(chunkNbt(version, pos, {mixed, solid}))}});
    const AnvilChunk c = loadOne(dir, pos);
    EXPECT_TRUE(c.full);
    EXPECT_EQ(c.dataVersion, version);
    expectSection(*c.chunk, mixed);
    EXPECT_EQ(c.chunk->get(4, solid.y * 16 + 9, 11), defaultBlocks().id("deepslate"));
    EXPECT_EQ(c.unknownCells, 0u);
    // A waterlogged slab holds water.
    const BlockId slab = defaultBlocks().id("oak_slab[type=top,waterlogged=true]");
    EXPECT_TRUE(defaultBlocks().holdsWater()[slab]);
  }
}

// Before 20w17a an index may span two longs: read as 1.16 reads them, 1.13's five-bit sections fail.
TEST(MinecraftSave, TheSpanningRuleDecidesBefore116) {
  const TestSection mixed = patterned(0);
  const auto spanning = packIndices(mixed.indices, 5, true), unspanned = packIndices(mixed.indices, 5, false);
  EXPECT_EQ(spanning.size(), 320u);
  EXPECT_EQ(unspanned.size(), 342u);
  const auto dir = scratch("span");
  // A 1.13 chunk holding 1.16's packing is refused with the counts.
  NbtCompound nbt = chunkNbt(kV1_13_2, {0, 0}, {mixed});
  writeRegion(dir / "region", {{{0, 0}, encodeNbt(nbt)}});
  EXPECT_NO_THROW(loadOne(dir, {0, 0}));
  NbtCompound wrong = chunkNbt(kV1_16, {0, 0}, {mixed});
  wrong[0].second.integer = kV1_13_2;  // 1.16's data, labelled 1.13
  writeRegion(dir / "region", {{{0, 0}, encodeNbt(wrong)}});
  const MinecraftSave save(dir);
  BlockStateMapper mapper(defaultBlocks(), kAir);
  try {
    save.load({0, 0}, mapper);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("342 longs of block data, 320 expected"), std::string::npos)
        << e.what();
  }
}

// Every compression Minecraft writes, and a chunk kept in c.X.Z.mcc beside its region.
TEST(MinecraftSave, ReadsEveryCompressionAndExternalChunks) {
  const auto dir = scratch("compress");
  const TestSection mixed = patterned(4);
  std::vector<RegionEntry> entries;
  const TestCompression kinds[] = {TestCompression::Gzip, TestCompression::Zlib, TestCompression::None,
                                   TestCompression::Lz4};
  for (int i = 0; i < 4; ++i) {
    const ChunkPos pos{i, 0};
    entries.push_back({pos, encodeNbt(chunkNbt(kV1_20_6, pos, {mixed})), kinds[i]});
  }
  entries.push_back({{4, 0}, encodeNbt(chunkNbt(kV1_20_6, {4, 0}, {mixed})), TestCompression::Zlib, true});
  entries.push_back({{5, 0}, encodeNbt(chunkNbt(kV1_20_6, {5, 0}, {mixed})), TestCompression::Lz4, true});
  writeRegion(dir / "region", entries);
  const MinecraftSave save(dir);
  EXPECT_EQ(save.chunks().size(), 6u);
  BlockStateMapper mapper(defaultBlocks(), kAir);
  for (const RegionEntry& e : entries) {
    SCOPED_TRACE(e.pos.x);
    const std::optional<AnvilChunk> c = save.load(e.pos, mapper);
    ASSERT_TRUE(c && c->full);
    expectSection(*c->chunk, mixed);
  }
}

// lz4-java's framing: a stream of several 64 KiB blocks, raw and compressed, checksummed.
TEST(MinecraftSave, Lz4BlockStreamsRoundTripAndCatchDamage) {
  std::vector<std::uint8_t> data(200000);
  std::mt19937 random(7);
  for (std::size_t i = 0; i < data.size(); ++i)
    data[i] = i < 100000 ? static_cast<std::uint8_t>(i / 300) : static_cast<std::uint8_t>(random());
  const std::vector<std::uint8_t> packed = encodeLz4Blocks(data);
  EXPECT_EQ(decodeLz4Blocks(packed, "test"), data);
  std::vector<std::uint8_t> damaged = packed;
  damaged[40] ^= 0x55;
  EXPECT_THROW(decodeLz4Blocks(damaged, "test"), Error);
}

// A renamed block is read by its chunk's version; a mod's block and an unknown property are counted.
TEST(MinecraftSave, NamesAreReadByTheChunksVersion) {
  const auto dir = scratch("names");
  TestSection s{.y = 4,
                .palette = {"stone_slab[type=bottom]", "grass", "sign[rotation=4]", "cauldron[level=2]",
                            "oak_log[axis=y,glowing=true]"},
                .indices = {}};
  s.indices.resize(4096);
  for (int i = 0; i < 4096; ++i) s.indices[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(i % 5);
  NbtCompound nbt = chunkNbt(kV1_13_2, {0, 0}, {s});
  // A mod's block, in another namespace.
  auto& palette = nbt[1].second.compound[3].second.list[0].compound[1].second.list;
  palette[4].compound[0].second.string = "create:cogwheel";
  writeRegion(dir / "region", {{{0, 0}, encodeNbt(nbt)}});
  const AnvilChunk c = loadOne(dir, {0, 0});
  const BlockRegistry& b = defaultBlocks();
  EXPECT_EQ(c.chunk->get(0, 64, 0), b.id("smooth_stone_slab[type=bottom]"));
  EXPECT_EQ(c.chunk->get(1, 64, 0), b.id("short_grass"));
  EXPECT_EQ(c.chunk->get(2, 64, 0), b.id("oak_sign[rotation=4]"));
  EXPECT_EQ(c.chunk->get(3, 64, 0), b.id("water_cauldron[level=2]"));
  EXPECT_EQ(c.unknownCells, 4096u / 5);
  EXPECT_EQ(c.unknownNames, (std::vector<std::string>{"create:cogwheel"}));
  // 1.14's new stone_slab is itself in a 1.16 chunk.
  const auto dir16 = scratch("names16");
  writeRegion(dir16 / "region",
              {{{0, 0},
                encodeNbt(chunkNbt(kV1_16, {0, 0},
                                   {{.y = 4,
                                     .palette = {"stone_slab[type=bottom]", "oak_log[axis=y,glowing=true]"},
                                     .indices = std::vector<std::uint16_t>(4096, 1)}}))}});
  const AnvilChunk later = loadOne(dir16, {0, 0});
  EXPECT_EQ(later.chunk->get(0, 64, 0), b.id("oak_log[axis=y]"));
  EXPECT_EQ(later.droppedPropertyCells, 4096u);
}

NbtValue& memberOf(NbtCompound& compound, const std::string& name) {
  for (auto& [key, value] : compound)
    if (key == name) return value;
  throw std::runtime_error("no " + name);
}

// Each column takes the tint of the biome its highest block stands in: 1.18's biome cells by name,
// 1.15-1.17's numeric cells, 1.13-1.14's numeric columns; the west half desert, the east half swamp,
// whose water and leaves have colours of their own.
TEST(MinecraftSave, ColumnsTakeTheirBiomesTint) {
  const TestSection ground{.y = 3, .palette = {"stone"}, .indices = {}};  // y 48..63
  const TintClimate desert = tintClimate(2.0f, 0.0f), swamp = tintClimate(0.8f, 0.9f);
  const auto expectHalves = [&](const std::filesystem::path& dir) {
    const AnvilChunk c = loadOne(dir, {0, 0});
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x) {
        const ColumnTint& t = c.chunk->tint(x, z);
        ASSERT_EQ(t.climate, x < 8 ? desert : swamp) << x << "," << z;
        ASSERT_EQ(t.water, (x < 8 ? BiomeColour{0x3F, 0x76, 0xE4, 255} : BiomeColour{0x61, 0x7B, 0x64, 255}));
        ASSERT_EQ(t.foliage, (x < 8 ? BiomeColour{} : BiomeColour{0x6A, 0x70, 0x39, 255}));
      }
  };
  {
    NbtCompound nbt = chunkNbt(kV1_18_1, {0, 0}, {ground});
    std::int64_t bits = 0;
    for (int i = 0; i < 64; ++i) bits |= std::int64_t{(i & 3) >= 2} << i;
    memberOf(nbt, "sections")
        .list[0]
        .compound.emplace_back(
            "biomes", nbtCompound({{"palette", nbtList(nbt::TagType::String, {nbtString("minecraft:desert"),
                                                                              nbtString("minecraft:swamp")})},
                                   {"data", nbtLongs({bits})}}));
    const auto dir = scratch("biomes118");
    writeRegion(dir / "region", {{{0, 0}, encodeNbt(nbt)}});
    expectHalves(dir);
  }
  for (const int cells : {1024, 256}) {
    NbtCompound nbt = chunkNbt(kV1_16, {0, 0}, {ground});
    std::vector<std::int64_t> ids(static_cast<std::size_t>(cells));
    for (int i = 0; i < cells; ++i)
      ids[static_cast<std::size_t>(i)] = ((cells == 256 ? i & 15 : (i & 3) << 2) >= 8) ? 6 : 2;
    memberOf(nbt, "Level").compound.emplace_back("Biomes", nbtInts(ids));
    const auto dir = scratch("biomes" + std::to_string(cells));
    writeRegion(dir / "region", {{{0, 0}, encodeNbt(nbt)}});
    expectHalves(dir);
  }
}

// Proto-chunks are counted, not decoded; level.dat gives the version and the player.
TEST(MinecraftSave, ProtoChunksAreLeftOutAndLevelDatRead) {
  const auto dir = scratch("proto");
  writeLevelDat(dir / "level.dat", kV1_20_6, "1.20.6");
  writeRegion(dir / "region",
              {{{0, 0}, encodeNbt(chunkNbt(kV1_20_6, {0, 0}, {patterned(0)}, "minecraft:structure_starts"))},
               {{1, 0}, encodeNbt(chunkNbt(kV1_20_6, {1, 0}, {patterned(0)}))}});
  const MinecraftSave save(dir);
  EXPECT_EQ(save.level().dataVersion, kV1_20_6);
  EXPECT_EQ(save.level().versionName, "1.20.6");
  ASSERT_TRUE(save.level().player);
  EXPECT_DOUBLE_EQ(save.level().player->z, -2.5);
  BlockStateMapper mapper(defaultBlocks(), kAir);
  EXPECT_FALSE(save.load({0, 0}, mapper)->full);
  EXPECT_FALSE(save.load({0, 0}, mapper)->chunk);
  EXPECT_TRUE(save.load({1, 0}, mapper)->full);
  // 26.1's layout, dimensions/minecraft/overworld/region, is found too.
  const auto moved = scratch("dims");
  writeRegion(moved / "dimensions" / "minecraft" / "overworld" / "region",
              {{{1, 0}, encodeNbt(chunkNbt(kV1_20_6, {1, 0}, {patterned(0)}))}});
  EXPECT_EQ(MinecraftSave(moved).chunks().size(), 1u);
}

TEST(MinecraftSave, APre113SaveIsRefusedNamingItsVersion) {
  const auto dir = scratch("old");
  writeLevelDat(dir / "level.dat", 1343, "1.12.2");
  writeRegion(dir / "region", {{{0, 0}, encodeNbt(chunkNbt(kV1_16, {0, 0}, {patterned(0)}))}});
  try {
    MinecraftSave save(dir);
    ADD_FAILURE() << "opened";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("1.12.2"), std::string::npos) << e.what();
  }
}

// What the loader must report, by file and chunk, with the rest of the save still read.
std::string errorOf(const std::filesystem::path& dir, ChunkPos pos) {
  const MinecraftSave save(dir);
  BlockStateMapper mapper(defaultBlocks(), kAir);
  try {
    save.load(pos, mapper);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void writeRaw(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> readRaw(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(MinecraftSave, DamagedInputIsReportedAndLeftOut) {
  const auto dir = scratch("damage");
  const TestSection mixed = patterned(4);
  std::vector<RegionEntry> entries;
  for (int i = 0; i < 8; ++i) entries.push_back({{i, 0}, encodeNbt(chunkNbt(kV1_18_1, {i, 0}, {mixed}))});
  // Chunk 1 claims to be elsewhere; chunk 2's palette index is past its palette.
  entries[1].nbt = encodeNbt(chunkNbt(kV1_18_1, {9, 9}, {mixed}));
  TestSection shortPalette = mixed;
  shortPalette.palette.resize(10);
  entries[2].nbt = encodeNbt(chunkNbt(kV1_18_1, {2, 0}, {shortPalette}));
  // Chunk 3: compounds nested 10 000 deep; chunk 4: a long array claiming 2^31 - 1 entries.
  std::vector<std::uint8_t> deep{10, 0, 0};
  for (int i = 0; i < 10000; ++i) deep.insert(deep.end(), {10, 0, 1, 'a'});
  entries[3].nbt = deep;
  entries[4].nbt = {10, 0, 0, 12, 0, 1, 'a', 0x7f, 0xff, 0xff, 0xff, 0, 0, 0, 0};
  // Chunk 5: a bomb, 100 MiB of zeros.
  entries[5].nbt = std::vector<std::uint8_t>(100u << 20, 0);
  const auto region = writeRegion(dir / "region", entries);
  // Chunk 6's compression byte becomes 127.
  std::vector<std::uint8_t> bytes = readRaw(region);
  const std::size_t sector6 =
      (std::size_t(bytes[6 * 4]) << 16 | std::size_t(bytes[6 * 4 + 1]) << 8 | bytes[6 * 4 + 2]);
  bytes[sector6 * 4096 + 4] = 127;
  writeRaw(region, bytes);

  EXPECT_EQ(errorOf(dir, {0, 0}), "");
  EXPECT_NE(errorOf(dir, {1, 0}).find("r.0.0.mca chunk (1, 0): says it is chunk (9, 9)"), std::string::npos);
  EXPECT_NE(errorOf(dir, {2, 0}).find("past its 10 entries"), std::string::npos) << errorOf(dir, {2, 0});
  EXPECT_NE(errorOf(dir, {3, 0}).find("nested deeper than 512"), std::string::npos) << errorOf(dir, {3, 0});
  EXPECT_NE(errorOf(dir, {4, 0}).find("needs 17179869176 bytes"), std::string::npos) << errorOf(dir, {4, 0});
  EXPECT_NE(errorOf(dir, {5, 0}).find("decompression bomb"), std::string::npos) << errorOf(dir, {5, 0});
  EXPECT_NE(errorOf(dir, {6, 0}).find("unknown compression type 127"), std::string::npos)
      << errorOf(dir, {6, 0});
  EXPECT_EQ(errorOf(dir, {7, 0}), "");

  // Header damage: slot 7 points past the end, slot 0 onto slot 1's sectors.
  bytes = readRaw(region);
  bytes[7 * 4] = 0x7f;
  std::copy(bytes.begin() + 4, bytes.begin() + 8, bytes.begin());
  writeRaw(region, bytes);
  const MinecraftSave save(dir);
  ASSERT_EQ(save.problems().size(), 2u);
  EXPECT_NE(save.problems()[0].find("chunk (7, 0): sectors"), std::string::npos) << save.problems()[0];
  EXPECT_NE(save.problems()[1].find("overlap"), std::string::npos) << save.problems()[1];
  EXPECT_EQ(save.chunks().size(), 5u);  // 0 and 1 overlap, 7 is out

  // A zero-length region is empty; a truncated header leaves its region out; the save still opens.
  writeRaw(dir / "region" / "r.1.0.mca", {});
  writeRaw(dir / "region" / "r.2.0.mca", std::vector<std::uint8_t>(5000, 0));
  const MinecraftSave more(dir);
  EXPECT_EQ(more.chunks().size(), 5u);
  ASSERT_EQ(more.problems().size(), 3u);
  EXPECT_NE(more.problems()[2].find("r.2.0.mca: 5000 bytes, shorter than the 8 KiB header"),
            std::string::npos)
      << more.problems()[2];
}

// The real saves: every chunk read, nothing unknown, and the surface where the save's own heightmaps say.
struct RealWorld {
  const char* path;
  std::size_t chunks, full;
};

TEST(MinecraftSave, RealSavesReadWithNothingUnknown) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const RealWorld worlds[] = {{"go-mc-1.18.1", 593, 593},
                              {"prismarine/1.13.2", 189, 75},
                              {"prismarine/1.16", 253, 253},
                              {"prismarine/1.20.6", 225, 16}};
  for (const RealWorld& w : worlds) {
    SCOPED_TRACE(w.path);
    const MinecraftSave save(testData() / "worlds" / w.path);
    EXPECT_TRUE(save.problems().empty());
    BlockStateMapper mapper(defaultBlocks(), kAir);
    std::size_t chunks = 0, full = 0, unknown = 0, dropped = 0;
    for (const ChunkPos pos : save.chunks()) {
      const std::optional<AnvilChunk> c = save.load(pos, mapper);
      ++chunks;
      full += c->full;
      unknown += c->unknownCells;
      dropped += c->droppedPropertyCells;
    }
    EXPECT_EQ(chunks, w.chunks);
    EXPECT_EQ(full, w.full);
    EXPECT_EQ(unknown, 0u);
    EXPECT_EQ(dropped, 0u);
  }
}

// go-mc's WORLD_SURFACE heightmap (9 bits, unspanned, value = top block + 1 - (-64)) against the blocks.
TEST(MinecraftSave, TheGoMcSurfaceIsWhereItsHeightmapsSay) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const auto dir = testData() / "worlds" / "go-mc-1.18.1";
  const MinecraftSave save(dir);
  BlockStateMapper mapper(defaultBlocks(), kAir);
  std::size_t columns = 0;
  for (const ChunkPos pos : save.chunks()) {
    const int rx = pos.x >> 5, rz = pos.z >> 5;
    const AnvilRegion region(dir / "region" / ("r." + std::to_string(rx) + "." + std::to_string(rz) + ".mca"),
                             rx, rz);
    const std::vector<std::uint8_t> raw = *region.read(pos);
    const nbt::Document doc = nbt::parse(raw, "test");
    const nbt::Tag* maps = doc.root.find("Heightmaps", nbt::TagType::Compound);
    ASSERT_TRUE(maps);
    const auto longs = maps->find("WORLD_SURFACE", nbt::TagType::LongArray)->longs();
    ASSERT_EQ(longs.size(), 37u);
    const AnvilChunk c = decodeAnvilChunk(doc.root, pos, mapper, "test");
    for (int i = 0; i < 256; ++i) {
      const int height = static_cast<int>(
          (static_cast<std::uint64_t>(longs[static_cast<std::size_t>(i / 7)]) >> (9 * (i % 7))) & 511);
      const int top = height - 1 + kMinY, x = i & 15, z = i >> 4;
      ASSERT_NE(c.chunk->get(x, top, z), kAir) << pos.x << "," << pos.z << " column " << i;
      ASSERT_EQ(c.chunk->get(x, top + 1, z), kAir) << pos.x << "," << pos.z << " column " << i;
      ++columns;
    }
  }
  EXPECT_EQ(columns, 593u * 256u);
}

// Reading never writes: every file of a save, byte for byte and by time, is as it was.
TEST(MinecraftSave, ReadingLeavesEveryFileAsItWas) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const auto source = testData() / "worlds" / "go-mc-1.18.1";
  const auto dir = scratch("untouched");
  std::filesystem::copy(source, dir, std::filesystem::copy_options::recursive);
  // The test data is read-only; the copy is made writable so the next run can clear it.
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    std::filesystem::permissions(e.path(), std::filesystem::perms::owner_write,
                                 std::filesystem::perm_options::add);
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all, std::filesystem::perm_options::add);
  std::map<std::filesystem::path, std::pair<std::vector<std::uint8_t>, std::filesystem::file_time_type>>
      before;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) before[e.path()] = {readRaw(e.path()), e.last_write_time()};
  {
    const MinecraftSave save(dir);
    BlockStateMapper mapper(defaultBlocks(), kAir);
    for (const ChunkPos pos : save.chunks()) save.load(pos, mapper);
  }
  std::size_t files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    ASSERT_TRUE(before.contains(e.path())) << "new file " << e.path();
    EXPECT_EQ(before[e.path()].first, readRaw(e.path()));
    EXPECT_EQ(before[e.path()].second, e.last_write_time());
    ++files;
  }
  EXPECT_EQ(files, before.size());
}

}  // namespace
}  // namespace terrasol
