#pragma once
// A region file holds the saved chunks of a 32 x 32 chunk area (as in Minecraft), as an append-only log:
//
//   file   = "TSREGN01" (8 bytes), then records back to back
//   record = 32-byte header + payload (a compressed chunk, chunk_codec.h), little-endian:
//              u32 magic "TSCK" | i32 chunk x | i32 chunk z | u32 payload size | u64 sequence |
//              u64 XXH3-64 of the first 24 header bytes and the payload
//
// Saving a chunk appends a record; the newest valid record of a chunk wins. Nothing already written is
// ever changed in place, so a process killed at any byte can only leave a torn record at the end, and
// every chunk saved before it stays readable. On open the file is scanned: a torn tail or a record
// whose checksum fails is reported (file, chunk, byte offset), its bytes are copied into
// "<file>.corrupt/" before anything else happens, and the scan resynchronises on the next record
// magic, so the rest of the region still loads. When superseded records make up most of the file it
// is rewritten compactly into a temporary file that atomically replaces it.
//
// Not thread-safe: WorldStorage serialises access.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "world/coords.h"

namespace terrasol {

struct RegionPos {
  int x = 0, z = 0;
  static constexpr RegionPos of(ChunkPos c) { return {c.x >> 5, c.z >> 5}; }
  friend constexpr bool operator==(const RegionPos&, const RegionPos&) = default;
};

class RegionFile {
 public:
  static constexpr std::size_t kHeaderSize = 8;
  static constexpr std::size_t kRecordHeaderSize = 32;
  static constexpr std::uint32_t kMaxPayload = 4u << 20;

  // Opens or creates the file. Problems found while scanning are in problems(); only an I/O failure
  // (cannot create, read or write) throws Error.
  RegionFile(std::filesystem::path path, RegionPos region);
  ~RegionFile();
  RegionFile(const RegionFile&) = delete;
  RegionFile& operator=(const RegionFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The newest valid payload saved for `chunk`, or nothing.
  std::optional<std::vector<std::uint8_t>> read(ChunkPos chunk) const;
  // Appends a record. Throws Error naming the file and chunk if the write fails (the file is then
  // cut back to its previous end, so no torn record remains).
  void write(ChunkPos chunk, const std::vector<std::uint8_t>& payload);
  // Forces written records to disk (fdatasync).
  void sync();
  // Rewrites the file without superseded records when they are over half of it. Returns true if it did.
  bool compactIfWasteful();

  const std::vector<std::string>& problems() const { return problems_; }
  std::size_t chunkCount() const { return index_.size(); }
  std::uint64_t fileSize() const { return size_; }

 private:
  struct Entry {
    std::uint64_t offset;  // of the record header
    std::uint32_t size;    // payload bytes
    std::uint64_t sequence;
  };

  // What a record's header says, as far as the bytes go.
  struct RecordView {
    bool magicOk = false, whole = false;
    ChunkPos chunk;
    std::uint32_t size = 0;
    std::string name, label;  // for messages, and for the names of kept-aside files
  };
  static RecordView viewRecord(const std::vector<std::uint8_t>& bytes, std::uint64_t offset);

  void scan();
  std::uint64_t scanRecord(const std::vector<std::uint8_t>& bytes, std::uint64_t offset);
  void cutTornTail(const std::vector<std::uint8_t>& bytes, std::uint64_t offset, const RecordView& r);
  void indexRecord(ChunkPos chunk, const Entry& entry);
  void keepAside(const std::vector<std::uint8_t>& bytes, std::uint64_t offset, std::uint64_t length,
                 const std::string& label);
  void report(std::uint64_t offset, const std::string& what);
  static int localIndex(ChunkPos c) { return (c.z & 31) * 32 + (c.x & 31); }

  std::filesystem::path path_;
  RegionPos region_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::uint64_t nextSequence_ = 1;
  std::uint64_t liveBytes_ = 0;
  std::unordered_map<int, Entry> index_;
  std::vector<std::string> problems_;
};

}  // namespace terrasol
