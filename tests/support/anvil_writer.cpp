#include "support/anvil_writer.h"

#include <lz4.h>
#include <zlib.h>

#include <bit>
#include <fstream>
#include <map>
#include <stdexcept>

#include "minecraft/chunk_compression.h"

namespace terrasol::testing {
namespace {

using nbt::TagType;

NbtValue of(TagType t) {
  NbtValue v;
  v.type = t;
  return v;
}

void big(std::vector<std::uint8_t>& out, std::uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

void writeString(std::vector<std::uint8_t>& out, const std::string& s) {
  big(out, s.size(), 2);
  out.insert(out.end(), s.begin(), s.end());
}

void writePayload(std::vector<std::uint8_t>& out, const NbtValue& v) {
  switch (v.type) {
    case TagType::Byte:
      big(out, static_cast<std::uint64_t>(v.integer), 1);
      break;
    case TagType::Short:
      big(out, static_cast<std::uint64_t>(v.integer), 2);
      break;
    case TagType::Int:
      big(out, static_cast<std::uint64_t>(v.integer), 4);
      break;
    case TagType::Long:
      big(out, static_cast<std::uint64_t>(v.integer), 8);
      break;
    case TagType::Float:
      big(out, std::bit_cast<std::uint32_t>(static_cast<float>(v.real)), 4);
      break;
    case TagType::Double:
      big(out, std::bit_cast<std::uint64_t>(v.real), 8);
      break;
    case TagType::String:
      writeString(out, v.string);
      break;
    case TagType::ByteArray:
    case TagType::IntArray:
    case TagType::LongArray: {
      const int width = v.type == TagType::ByteArray ? 1 : v.type == TagType::IntArray ? 4 : 8;
      big(out, v.longs.size(), 4);
      for (const std::int64_t x : v.longs) big(out, static_cast<std::uint64_t>(x), width);
      break;
    }
    case TagType::List:
      out.push_back(static_cast<std::uint8_t>(v.listType));
      big(out, v.list.size(), 4);
      for (const NbtValue& item : v.list) writePayload(out, item);
      break;
    case TagType::Compound:
      for (const auto& [name, member] : v.compound) {
        out.push_back(static_cast<std::uint8_t>(member.type));
        writeString(out, name);
        writePayload(out, member);
      }
      out.push_back(0);
      break;
    case TagType::End:
      break;
  }
}

std::vector<std::uint8_t> deflateWith(const std::vector<std::uint8_t>& raw, int windowBits) {
  z_stream z{};
  deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, windowBits, 8, Z_DEFAULT_STRATEGY);
  std::vector<std::uint8_t> out(deflateBound(&z, raw.size()) + 32);
  z.next_in = const_cast<Bytef*>(raw.data());
  z.avail_in = static_cast<uInt>(raw.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

// "oak_log[axis=x,waterlogged=true]" as a palette compound.
NbtValue paletteEntry(const std::string& state) {
  NbtCompound entry;
  const std::size_t open = state.find('[');
  entry.emplace_back("Name", nbtString("minecraft:" + state.substr(0, open)));
  if (open != std::string::npos) {
    NbtCompound props;
    const std::string inner = state.substr(open + 1, state.size() - open - 2);
    std::size_t start = 0;
    while (start < inner.size()) {
      std::size_t end = inner.find(',', start);
      if (end == std::string::npos) end = inner.size();
      const std::string kv = inner.substr(start, end - start);
      const std::size_t eq = kv.find('=');
      props.emplace_back(kv.substr(0, eq), nbtString(kv.substr(eq + 1)));
      start = end + 1;
    }
    entry.emplace_back("Properties", nbtCompound(props));
  }
  return nbtCompound(entry);
}

}  // namespace

NbtValue nbtByte(int v) {
  NbtValue x = of(TagType::Byte);
  x.integer = v;
  return x;
}
NbtValue nbtInt(std::int64_t v) {
  NbtValue x = of(TagType::Int);
  x.integer = v;
  return x;
}
NbtValue nbtLong(std::int64_t v) {
  NbtValue x = of(TagType::Long);
  x.integer = v;
  return x;
}
NbtValue nbtDouble(double v) {
  NbtValue x = of(TagType::Double);
  x.real = v;
  return x;
}
NbtValue nbtString(std::string v) {
  NbtValue x = of(TagType::String);
  x.string = std::move(v);
  return x;
}
NbtValue nbtLongs(std::vector<std::int64_t> v) {
  NbtValue x = of(TagType::LongArray);
  x.longs = std::move(v);
  return x;
}
NbtValue nbtInts(std::vector<std::int64_t> v) {
  NbtValue x = of(TagType::IntArray);
  x.longs = std::move(v);
  return x;
}
NbtValue nbtList(TagType type, std::vector<NbtValue> items) {
  NbtValue x = of(TagType::List);
  x.listType = type;
  x.list = std::move(items);
  return x;
}
NbtValue nbtCompound(NbtCompound members) {
  NbtValue x = of(TagType::Compound);
  x.compound = std::move(members);
  return x;
}

std::vector<std::uint8_t> encodeNbt(const NbtCompound& root) {
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(TagType::Compound)};
  writeString(out, "");
  writePayload(out, nbtCompound(root));
  return out;
}

std::vector<std::int64_t> packIndices(const std::vector<std::uint16_t>& indices, int bits, bool spanning) {
  std::vector<std::uint64_t> longs;
  if (spanning) {
    longs.assign(indices.size() * static_cast<std::size_t>(bits) / 64, 0);
    for (std::size_t i = 0; i < indices.size(); ++i) {
      const std::size_t bit = i * static_cast<std::size_t>(bits), word = bit / 64, shift = bit % 64;
      longs[word] |= std::uint64_t{indices[i]} << shift;
      if (shift + static_cast<std::size_t>(bits) > 64)
        longs[word + 1] |= std::uint64_t{indices[i]} >> (64 - shift);
    }
  } else {
    const std::size_t per = 64 / static_cast<std::size_t>(bits);
    longs.assign((indices.size() + per - 1) / per, 0);
    for (std::size_t i = 0; i < indices.size(); ++i)
      longs[i / per] |= std::uint64_t{indices[i]} << ((i % per) * static_cast<std::size_t>(bits));
  }
  return {longs.begin(), longs.end()};
}

NbtCompound chunkNbt(int dataVersion, ChunkPos pos, const std::vector<TestSection>& sections,
                     const std::string& status) {
  const bool modern = dataVersion >= 2844, spanning = dataVersion < 2529;
  std::vector<NbtValue> list;
  for (const TestSection& s : sections) {
    std::vector<NbtValue> palette;
    for (const std::string& state : s.palette) palette.push_back(paletteEntry(state));
    NbtCompound section{{"Y", nbtByte(s.y)}};
    std::vector<std::uint16_t> indices = s.indices;
    if (indices.empty() && !modern) indices.assign(4096, 0);  // before 1.18 a lone entry still has data
    const int bits = std::max(4, static_cast<int>(std::bit_width(s.palette.size() - 1)));
    if (modern) {
      NbtCompound states{{"palette", nbtList(TagType::Compound, palette)}};
      if (!indices.empty()) states.emplace_back("data", nbtLongs(packIndices(indices, bits, false)));
      section.emplace_back("block_states", nbtCompound(states));
      if (!s.biome.empty())
        section.emplace_back("biomes",
                             nbtCompound({{"palette", nbtList(TagType::String, {nbtString(s.biome)})}}));
    } else {
      section.emplace_back("Palette", nbtList(TagType::Compound, palette));
      section.emplace_back("BlockStates", nbtLongs(packIndices(indices, bits, spanning)));
    }
    list.push_back(nbtCompound(section));
  }
  NbtCompound body{{"xPos", nbtInt(pos.x)}, {"zPos", nbtInt(pos.z)}, {"Status", nbtString(status)}};
  if (modern) {
    body.emplace_back("yPos", nbtInt(-4));
    body.emplace_back("sections", nbtList(TagType::Compound, list));
    body.insert(body.begin(), {"DataVersion", nbtInt(dataVersion)});
    return body;
  }
  body.emplace_back("Sections", nbtList(TagType::Compound, list));
  return {{"DataVersion", nbtInt(dataVersion)}, {"Level", nbtCompound(body)}};
}

std::vector<std::uint8_t> compress(TestCompression c, const std::vector<std::uint8_t>& raw) {
  switch (c) {
    case TestCompression::Gzip:
      return deflateWith(raw, 15 + 16);
    case TestCompression::Zlib:
      return deflateWith(raw, 15);
    case TestCompression::None:
      return raw;
    case TestCompression::Lz4:
      return encodeLz4Blocks(raw);
  }
  return raw;
}

std::filesystem::path writeRegion(const std::filesystem::path& dir, const std::vector<RegionEntry>& entries) {
  std::filesystem::create_directories(dir);
  const int rx = entries.front().pos.x >> 5, rz = entries.front().pos.z >> 5;
  std::vector<std::uint8_t> file(8192, 0);
  for (const RegionEntry& e : entries) {
    const std::vector<std::uint8_t> data = compress(e.compression, e.nbt);
    std::vector<std::uint8_t> record;
    const std::uint8_t type = static_cast<std::uint8_t>(e.compression) | (e.external ? 128 : 0);
    if (e.external) {
      std::ofstream(dir / ("c." + std::to_string(e.pos.x) + "." + std::to_string(e.pos.z) + ".mcc"),
                    std::ios::binary)
          .write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
      big(record, 1, 4);
      record.push_back(type);
    } else {
      big(record, data.size() + 1, 4);
      record.push_back(type);
      record.insert(record.end(), data.begin(), data.end());
    }
    const std::size_t sector = file.size() / 4096, sectors = (record.size() + 4095) / 4096;
    record.resize(sectors * 4096, 0);
    file.insert(file.end(), record.begin(), record.end());
    const std::size_t slot = static_cast<std::size_t>((e.pos.x & 31) + (e.pos.z & 31) * 32);
    const std::uint32_t location = static_cast<std::uint32_t>(sector << 8 | sectors);
    for (int i = 0; i < 4; ++i)
      file[slot * 4 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(location >> (24 - 8 * i));
  }
  const auto path = dir / ("r." + std::to_string(rx) + "." + std::to_string(rz) + ".mca");
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(file.data()), static_cast<std::streamsize>(file.size()));
  return path;
}

void writeLevelDat(const std::filesystem::path& file, int dataVersion, const std::string& versionName) {
  const NbtCompound data{
      {"DataVersion", nbtInt(dataVersion)},
      {"Version", nbtCompound({{"Name", nbtString(versionName)}})},
      {"SpawnX", nbtInt(8)},
      {"SpawnY", nbtInt(70)},
      {"SpawnZ", nbtInt(8)},
      {"Player",
       nbtCompound({{"Pos", nbtList(TagType::Double, {nbtDouble(1.5), nbtDouble(65), nbtDouble(-2.5)})}})}};
  const std::vector<std::uint8_t> packed =
      compress(TestCompression::Gzip, encodeNbt({{"Data", nbtCompound(data)}}));
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(packed.data()), static_cast<std::streamsize>(packed.size()));
}

}  // namespace terrasol::testing
