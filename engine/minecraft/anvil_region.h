#pragma once
// One Minecraft region file (r.X.Z.mca, 32 x 32 chunks), read-only. Layout: an 8 KiB header of 1024
// big-endian locations (sector offset << 8 | sector count, 4 KiB sectors, slot (x & 31) + (z & 31) * 32)
// and 1024 timestamps; a chunk's sectors hold a u32 length (counting the type byte), the type byte
// (chunk_compression.h; + 128: the data is in c.X.Z.mcc beside the region) and the data.
//
// The file is opened read-only and never written. Slots pointing into the header, past the end, or
// over another chunk's sectors are left out and reported in problems(); a 0-byte file (real saves have
// them) is an empty region. read() is thread-safe: it uses pread and no shared position.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "world/coords.h"

namespace terrasol {

class AnvilRegion {
 public:
  static constexpr std::size_t kSectorBytes = 4096;
  static constexpr int kSlots = 1024;

  // Throws Error naming the file when it cannot be opened or its header is cut short.
  AnvilRegion(std::filesystem::path path, int regionX, int regionZ);
  ~AnvilRegion();
  AnvilRegion(const AnvilRegion&) = delete;
  AnvilRegion& operator=(const AnvilRegion&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The chunks the header lists and that passed its checks.
  std::vector<ChunkPos> chunks() const;
  bool contains(ChunkPos chunk) const { return slots_[slotOf(chunk)].sectors > 0; }
  // The chunk's NBT, decompressed, or nothing when the region does not hold it. Throws Error naming the
  // file, the chunk and what is wrong (a bad length or compression byte, damaged data, a missing .mcc).
  std::optional<std::vector<std::uint8_t>> read(ChunkPos chunk) const;

  const std::vector<std::string>& problems() const { return problems_; }
  // "r.0.0.mca chunk (3, -4)": how messages name a chunk.
  std::string describe(ChunkPos chunk) const;

 private:
  struct Slot {
    std::uint32_t sector = 0, sectors = 0;
  };
  static int slotOf(ChunkPos c) { return (c.x & 31) + (c.z & 31) * 32; }
  ChunkPos chunkOf(int slot) const { return {regionX_ * 32 + slot % 32, regionZ_ * 32 + slot / 32}; }
  void readHeader();
  std::vector<std::uint8_t> readBytes(std::uint64_t offset, std::size_t size, const std::string& what) const;

  std::filesystem::path path_;
  int regionX_, regionZ_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  Slot slots_[kSlots];
  std::vector<std::string> problems_;
};

}  // namespace terrasol
