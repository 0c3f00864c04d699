#pragma once
// Writes Minecraft saves for tests: NBT trees, chunks of each format era, region files (with any
// compression, .mcc files and deliberate damage). The reader under test never sees this code.

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "minecraft/nbt.h"
#include "world/coords.h"

namespace terrasol::testing {

struct NbtValue;
using NbtCompound = std::vector<std::pair<std::string, NbtValue>>;

struct NbtValue {
  nbt::TagType type = nbt::TagType::End;
  std::int64_t integer = 0;
  double real = 0;
  std::string string;
  std::vector<std::int64_t> longs;  // LongArray; IntArray and ByteArray too, narrowed when written
  nbt::TagType listType = nbt::TagType::End;
  std::vector<NbtValue> list;
  NbtCompound compound;
};

NbtValue nbtByte(int v);
NbtValue nbtInt(std::int64_t v);
NbtValue nbtLong(std::int64_t v);
NbtValue nbtDouble(double v);
NbtValue nbtString(std::string v);
NbtValue nbtLongs(std::vector<std::int64_t> v);
NbtValue nbtInts(std::vector<std::int64_t> v);
NbtValue nbtList(nbt::TagType type, std::vector<NbtValue> items);
NbtValue nbtCompound(NbtCompound members);

// A named root compound, as files and chunks hold it.
std::vector<std::uint8_t> encodeNbt(const NbtCompound& root);

// Packs 4096 palette indices at `bits` each, spanning longs (before 1.16) or not.
std::vector<std::int64_t> packIndices(const std::vector<std::uint16_t>& indices, int bits, bool spanning);

// One section of a test chunk: palette entries as "name" or "name[k=v,...]", and an index per cell
// ((y << 8) | (z << 4) | x); no indices with one entry writes no data (1.18's form). From 1.18 on, a
// biome names the section's one biome (none written without).
struct TestSection {
  int y = 0;
  std::vector<std::string> palette;
  std::vector<std::uint16_t> indices;
  std::string biome = {};
};

// A chunk's NBT in the layout of `dataVersion` (Level-wrapped before 1.18).
NbtCompound chunkNbt(int dataVersion, ChunkPos pos, const std::vector<TestSection>& sections,
                     const std::string& status = "minecraft:full");

enum class TestCompression : std::uint8_t { Gzip = 1, Zlib = 2, None = 3, Lz4 = 4 };
std::vector<std::uint8_t> compress(TestCompression c, const std::vector<std::uint8_t>& raw);

struct RegionEntry {
  ChunkPos pos;
  std::vector<std::uint8_t> nbt;  // uncompressed
  TestCompression compression = TestCompression::Zlib;
  bool external = false;  // data in c.X.Z.mcc, the type byte + 128
};
// Writes DIR/r.X.Z.mca for the region holding the entries (and any .mcc files), Minecraft's way.
std::filesystem::path writeRegion(const std::filesystem::path& dir, const std::vector<RegionEntry>& entries);
// A gzip'd level.dat with Data.DataVersion, Data.Version.Name and a player position.
void writeLevelDat(const std::filesystem::path& file, int dataVersion, const std::string& versionName);

}  // namespace terrasol::testing
