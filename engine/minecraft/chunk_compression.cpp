#include "minecraft/chunk_compression.h"

#include <lz4.h>
#include <xxhash.h>
#include <zlib.h>

#include <cstring>
#include <string>

#include "core/error.h"

namespace terrasol {
namespace {

constexpr char kLz4Magic[] = "LZ4Block";
constexpr std::size_t kLz4MagicSize = 8;
constexpr std::size_t kLz4HeaderSize = kLz4MagicSize + 1 + 4 + 4 + 4;
constexpr std::uint8_t kLz4Raw = 0x10, kLz4Compressed = 0x20;
constexpr std::uint32_t kLz4Seed = 0x9747b28c;
constexpr std::size_t kLz4BlockSize = 64u << 10;  // lz4-java's default

[[noreturn]] void fail(std::string_view what, const std::string& message) {
  throw Error(std::string(what) + ": " + message);
}

std::uint32_t littleU32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
         std::uint32_t(p[3]) << 24;
}

void putLittleU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint32_t lz4Checksum(const std::uint8_t* data, std::size_t size) {
  return XXH32(data, size, kLz4Seed) & 0x0FFFFFFFu;
}

std::string tooBig() {
  return "inflates past " + std::to_string(kMaxChunkBytes >> 20) + " MiB (a decompression bomb?)";
}

}  // namespace

std::vector<std::uint8_t> inflateAny(std::span<const std::uint8_t> data, std::string_view what) {
  z_stream z{};
  // 15 + 32: a 32 KiB window, with gzip or zlib headers detected.
  if (inflateInit2(&z, 15 + 32) != Z_OK) fail(what, "zlib could not start");
  std::vector<std::uint8_t> out(std::max<std::size_t>(data.size() * 4, 4096));
  z.next_in = const_cast<Bytef*>(data.data());
  z.avail_in = static_cast<uInt>(data.size());
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    if (z.total_out == out.size()) {
      if (out.size() >= kMaxChunkBytes) {
        inflateEnd(&z);
        fail(what, tooBig());
      }
      out.resize(std::min(out.size() * 2, kMaxChunkBytes));
    }
    z.next_out = out.data() + z.total_out;
    z.avail_out = static_cast<uInt>(out.size() - z.total_out);
    status = inflate(&z, Z_NO_FLUSH);
    if (status == Z_BUF_ERROR && z.avail_in == 0) status = Z_DATA_ERROR;  // ends early
    if (status != Z_OK && status != Z_STREAM_END) {
      const std::string message = z.msg ? z.msg : "truncated";
      inflateEnd(&z);
      fail(what, "compressed data is damaged (" + message + ")");
    }
  }
  out.resize(z.total_out);
  inflateEnd(&z);
  return out;
}

std::vector<std::uint8_t> decodeLz4Blocks(std::span<const std::uint8_t> data, std::string_view what) {
  std::vector<std::uint8_t> out;
  std::size_t pos = 0;
  while (pos < data.size()) {
    const std::string at = "LZ4 block at byte " + std::to_string(pos) + ": ";
    if (data.size() - pos < kLz4HeaderSize || std::memcmp(data.data() + pos, kLz4Magic, kLz4MagicSize) != 0)
      fail(what, at + "no LZ4Block header");
    const std::uint8_t* h = data.data() + pos + kLz4MagicSize;
    const std::uint8_t method = h[0] & 0xF0;
    const std::uint32_t packed = littleU32(h + 1), original = littleU32(h + 5), check = littleU32(h + 9);
    pos += kLz4HeaderSize;
    if (original == 0 && packed == 0) break;  // the closing block
    if (method != kLz4Raw && method != kLz4Compressed)
      fail(what, at + "unknown method " + std::to_string(method));
    if (packed > data.size() - pos) fail(what, at + "runs past the end of the data");
    if (original > kMaxChunkBytes - out.size()) fail(what, tooBig());
    if (method == kLz4Raw && packed != original) fail(what, at + "raw block of two lengths");
    const std::size_t start = out.size();
    out.resize(start + original);
    if (method == kLz4Raw) {
      std::memcpy(out.data() + start, data.data() + pos, original);
    } else {
      const int n = LZ4_decompress_safe(reinterpret_cast<const char*>(data.data() + pos),
                                        reinterpret_cast<char*>(out.data() + start), static_cast<int>(packed),
                                        static_cast<int>(original));
      if (n != static_cast<int>(original)) fail(what, at + "LZ4 data is damaged");
    }
    if (lz4Checksum(out.data() + start, original) != check) fail(what, at + "checksum does not match");
    pos += packed;
  }
  return out;
}

std::vector<std::uint8_t> encodeLz4Blocks(std::span<const std::uint8_t> data) {
  std::vector<std::uint8_t> out;
  const auto header = [&](std::uint8_t method, std::uint32_t packed, std::uint32_t original,
                          std::uint32_t check) {
    out.insert(out.end(), kLz4Magic, kLz4Magic + kLz4MagicSize);
    out.push_back(static_cast<std::uint8_t>(method | 6));  // 6: log2(64 KiB) - 10
    putLittleU32(out, packed);
    putLittleU32(out, original);
    putLittleU32(out, check);
  };
  std::vector<char> buffer(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(kLz4BlockSize))));
  for (std::size_t pos = 0; pos < data.size(); pos += kLz4BlockSize) {
    const std::size_t size = std::min(kLz4BlockSize, data.size() - pos);
    const int packed = LZ4_compress_default(reinterpret_cast<const char*>(data.data() + pos), buffer.data(),
                                            static_cast<int>(size), static_cast<int>(buffer.size()));
    const std::uint32_t check = lz4Checksum(data.data() + pos, size);
    if (packed <= 0 || static_cast<std::size_t>(packed) >= size) {  // incompressible: stored raw
      header(kLz4Raw, static_cast<std::uint32_t>(size), static_cast<std::uint32_t>(size), check);
      out.insert(out.end(), data.begin() + static_cast<std::ptrdiff_t>(pos),
                 data.begin() + static_cast<std::ptrdiff_t>(pos + size));
    } else {
      header(kLz4Compressed, static_cast<std::uint32_t>(packed), static_cast<std::uint32_t>(size), check);
      out.insert(out.end(), buffer.begin(), buffer.begin() + packed);
    }
  }
  header(kLz4Raw, 0, 0, 0);
  return out;
}

std::vector<std::uint8_t> decompressChunk(ChunkCompression compression, std::span<const std::uint8_t> data,
                                          std::string_view what) {
  switch (compression) {
    case ChunkCompression::Gzip:
    case ChunkCompression::Zlib:
      return inflateAny(data, what);
    case ChunkCompression::None:
      if (data.size() > kMaxChunkBytes) fail(what, tooBig());
      return {data.begin(), data.end()};
    case ChunkCompression::Lz4:
      return decodeLz4Blocks(data, what);
  }
  fail(what, "unknown compression " + std::to_string(static_cast<int>(compression)));
}

}  // namespace terrasol
