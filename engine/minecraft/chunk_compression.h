#pragma once
// The compressions Minecraft writes a chunk's NBT with: its region files' type byte (1 gzip, 2 zlib,
// 3 none, 4 LZ4 as lz4-java's LZ4BlockOutputStream frames it). Every decoder stops at kMaxChunkBytes
// of output, so a decompression bomb is an error, not an out-of-memory kill.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace terrasol {

enum class ChunkCompression : std::uint8_t { Gzip = 1, Zlib = 2, None = 3, Lz4 = 4 };

// Far above any real chunk (a chunk too big for its region's 1 MiB sectors is still a few MiB).
inline constexpr std::size_t kMaxChunkBytes = 64u << 20;

// Throws terrasol::Error starting with `what` (the file and chunk) and saying what is wrong.
std::vector<std::uint8_t> decompressChunk(ChunkCompression compression, std::span<const std::uint8_t> data,
                                          std::string_view what);

// gzip or zlib (told apart by their headers), as level.dat and region chunks use them.
std::vector<std::uint8_t> inflateAny(std::span<const std::uint8_t> data, std::string_view what);

// lz4-java's block stream: blocks of "LZ4Block", a token (method 0x10 raw or 0x20 LZ4 in the high
// nibble), little-endian compressed and original lengths and a checksum (XXH32 seeded 0x9747b28c, kept
// to 28 bits as lz4-java's Checksum view does), until the data ends or an empty block closes it.
std::vector<std::uint8_t> decodeLz4Blocks(std::span<const std::uint8_t> data, std::string_view what);
// The same framing written (tests write LZ4 regions with it).
std::vector<std::uint8_t> encodeLz4Blocks(std::span<const std::uint8_t> data);

}  // namespace terrasol
