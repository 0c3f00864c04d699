#include "world/chunk_codec.h"

#include <zstd.h>

#include <unordered_map>

#include "core/error.h"

namespace terrasol {
namespace {

// 2: names are Minecraft's throughout. 1 named the full snow block "snow" and the snow layer
// "snow_layer", as Terrasol did before it followed Minecraft's block table.
constexpr std::uint8_t kVersion = 2;
// Largest possible uncompressed chunk: header, a full palette, 24 dense sections.
constexpr std::size_t kMaxRaw = 3 + 65536 * 256 + kSectionCount * (1 + 2 * Section::kVolume);
constexpr int kZstdLevel = 3;  // zstd's default: fast, and chunks shrink 20-100x anyway

void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(static_cast<std::uint8_t>(v & 0xFF));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
}

// A version-1 state name as today's registry names it.
std::string fromVersion1(const std::string& name) {
  if (name == "snow") return "snow_block";
  if (name.rfind("snow_layer", 0) == 0) return "snow" + name.substr(std::string_view("snow_layer").size());
  return name;
}

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t u8() { return need(1), data_[pos_++]; }
  std::uint16_t u16() {
    need(2);
    const auto v = static_cast<std::uint16_t>(data_[pos_] | data_[pos_ + 1] << 8);
    pos_ += 2;
    return v;
  }
  std::string bytes(std::size_t n) {
    need(n);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
    pos_ += n;
    return s;
  }
  bool atEnd() const { return pos_ == size_; }

 private:
  void need(std::size_t n) const {
    if (size_ - pos_ < n) throw Error("chunk data ends early at byte " + std::to_string(pos_));
  }
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<std::uint8_t> encodeChunk(const Chunk& chunk, const BlockRegistry& blocks) {
  std::vector<BlockId> toPalette(blocks.size(), 0xFFFF);
  std::vector<BlockId> palette;
  auto index = [&](BlockId id) {
    if (toPalette[id] == 0xFFFF) {
      toPalette[id] = static_cast<BlockId>(palette.size());
      palette.push_back(id);
    }
    return toPalette[id];
  };
  std::vector<std::uint8_t> body;
  for (int s = 0; s < kSectionCount; ++s) {
    const Section& section = chunk.section(s);
    if (const auto* dense = section.blocks()) {
      body.push_back(1);
      for (BlockId id : *dense) put16(body, index(id));
    } else {
      body.push_back(0);
      put16(body, index(section.uniformBlock()));
    }
  }
  std::vector<std::uint8_t> raw{kVersion};
  put16(raw, static_cast<std::uint16_t>(palette.size()));
  for (BlockId id : palette) {
    const std::string name = blocks.stateName(id);
    if (name.size() > 255) throw Error("block state name longer than 255 bytes: " + name);
    raw.push_back(static_cast<std::uint8_t>(name.size()));
    raw.insert(raw.end(), name.begin(), name.end());
  }
  raw.insert(raw.end(), body.begin(), body.end());

  std::vector<std::uint8_t> out(ZSTD_compressBound(raw.size()));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), kZstdLevel);
  if (ZSTD_isError(n)) throw Error(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

std::unique_ptr<Chunk> decodeChunk(ChunkPos pos, const std::uint8_t* data, std::size_t size,
                                   const BlockRegistry& blocks, std::vector<std::string>* unknownBlocks) {
  const unsigned long long rawSize = ZSTD_getFrameContentSize(data, size);
  if (rawSize == ZSTD_CONTENTSIZE_ERROR || rawSize == ZSTD_CONTENTSIZE_UNKNOWN || rawSize > kMaxRaw) {
    throw Error("not a valid compressed chunk");
  }
  std::vector<std::uint8_t> raw(rawSize);
  const std::size_t n = ZSTD_decompress(raw.data(), raw.size(), data, size);
  if (ZSTD_isError(n) || n != rawSize)
    throw Error(std::string("cannot decompress chunk: ") + ZSTD_getErrorName(n));

  Reader in(raw.data(), raw.size());
  const std::uint8_t version = in.u8();
  if (version != 1 && version != kVersion)
    throw Error("unsupported chunk version " + std::to_string(version));
  std::vector<BlockId> palette(in.u16());
  for (auto& id : palette) {
    std::string name = in.bytes(in.u8());
    if (version == 1) name = fromVersion1(name);
    bool found = false;
    id = blocks.find(name, &found);
    if (!found && unknownBlocks) unknownBlocks->push_back(name);
  }
  auto lookup = [&](std::uint16_t i) {
    if (i >= palette.size()) throw Error("palette index " + std::to_string(i) + " out of range");
    return palette[i];
  };
  auto chunk = std::make_unique<Chunk>(pos);
  for (int s = 0; s < kSectionCount; ++s) {
    Section& section = chunk->section(s);
    const std::uint8_t kind = in.u8();
    if (kind == 0) {
      section.fill(lookup(in.u16()));
    } else if (kind == 1) {
      for (BlockId& id : section.mutableBlocks()) id = lookup(in.u16());
      section.compact();  // unknown names may have made it uniform
    } else {
      throw Error("section " + std::to_string(s) + " has unknown kind " + std::to_string(kind));
    }
  }
  if (!in.atEnd()) throw Error("trailing bytes after the last section");
  return chunk;
}

}  // namespace terrasol
