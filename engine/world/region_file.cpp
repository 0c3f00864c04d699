#include "world/region_file.h"

#include <fcntl.h>
#include <unistd.h>
#include <xxhash.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.h"

namespace terrasol {
namespace {

constexpr char kFileMagic[RegionFile::kHeaderSize] = {'T', 'S', 'R', 'E', 'G', 'N', '0', '1'};
constexpr std::uint8_t kRecordMagic[4] = {'T', 'S', 'C', 'K'};

std::uint32_t get32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
std::uint64_t get64(const std::uint8_t* p) {
  return get32(p) | static_cast<std::uint64_t>(get32(p + 4)) << 32;
}
void put32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put64(std::uint8_t* p, std::uint64_t v) {
  put32(p, static_cast<std::uint32_t>(v));
  put32(p + 4, static_cast<std::uint32_t>(v >> 32));
}

std::uint64_t recordChecksum(const std::uint8_t* header, const std::uint8_t* payload, std::size_t size) {
  // The header's hash seeds the payload's, so both are covered.
  return XXH3_64bits_withSeed(payload, size, XXH3_64bits(header, 24));
}

std::vector<std::uint8_t> makeRecord(ChunkPos chunk, const std::uint8_t* payload, std::uint32_t size,
                                     std::uint64_t sequence) {
  std::vector<std::uint8_t> record(RegionFile::kRecordHeaderSize + size);
  std::memcpy(record.data(), kRecordMagic, 4);
  put32(&record[4], static_cast<std::uint32_t>(chunk.x));
  put32(&record[8], static_cast<std::uint32_t>(chunk.z));
  put32(&record[12], size);
  put64(&record[16], sequence);
  std::memcpy(record.data() + RegionFile::kRecordHeaderSize, payload, size);
  put64(&record[24], recordChecksum(record.data(), payload, size));
  return record;
}

std::string errnoText() {
  return std::strerror(errno);
}

// Makes a rename durable.
void syncDirectory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

void writeAll(int fd, const std::uint8_t* data, std::size_t size, std::uint64_t offset) {
  while (size > 0) {
    const ssize_t n = ::pwrite(fd, data, size, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(errnoText());
    data += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<std::uint64_t>(n);
  }
}

// Offset of the next record magic at or after `from`, or `bytes.size()`.
std::uint64_t findMagic(const std::vector<std::uint8_t>& bytes, std::uint64_t from) {
  for (std::uint64_t i = from; i + 4 <= bytes.size(); ++i) {
    if (std::memcmp(&bytes[i], kRecordMagic, 4) == 0) return i;
  }
  return bytes.size();
}

}  // namespace

RegionFile::RecordView RegionFile::viewRecord(const std::vector<std::uint8_t>& bytes, std::uint64_t offset) {
  RecordView r;
  const std::uint64_t left = bytes.size() - offset;
  const std::uint8_t* h = &bytes[offset];
  r.magicOk = left >= 4 && std::memcmp(h, kRecordMagic, 4) == 0;
  const bool coordsKnown = r.magicOk && left >= 12;
  if (coordsKnown) r.chunk = {static_cast<int>(get32(h + 4)), static_cast<int>(get32(h + 8))};
  r.size = left >= kRecordHeaderSize ? get32(h + 12) : 0;
  r.name = coordsKnown ? "chunk (" + std::to_string(r.chunk.x) + ", " + std::to_string(r.chunk.z) + ")"
                       : "a chunk (its coordinates were not written)";
  r.label =
      coordsKnown ? "chunk_" + std::to_string(r.chunk.x) + "_" + std::to_string(r.chunk.z) : "unknown_chunk";
  r.whole =
      r.magicOk && left >= kRecordHeaderSize && r.size <= kMaxPayload && kRecordHeaderSize + r.size <= left;
  return r;
}

RegionFile::RegionFile(std::filesystem::path path, RegionPos region)
    : path_(std::move(path)), region_(region) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error(locate(path_, 0, "cannot open region file: " + errnoText()));
  try {
    scan();
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

RegionFile::~RegionFile() {
  if (fd_ >= 0) ::close(fd_);
}

void RegionFile::report(std::uint64_t offset, const std::string& what) {
  problems_.push_back(path_.string() + ": byte " + std::to_string(offset) + ": " + what);
}

void RegionFile::keepAside(const std::vector<std::uint8_t>& bytes, std::uint64_t offset, std::uint64_t length,
                           const std::string& label) {
  const std::filesystem::path dir = path_.string() + ".corrupt";
  std::filesystem::create_directories(dir);
  const auto file = dir / (label + "_at_" + std::to_string(offset) + ".bin");
  if (std::filesystem::exists(file) && std::filesystem::file_size(file) == length) return;  // kept before
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data() + offset), static_cast<std::streamsize>(length));
  if (!out) throw Error(locate(file, 0, "cannot keep corrupt region bytes aside"));
  problems_.back() += "; its bytes are kept in " + file.string();
}

void RegionFile::scan() {
  const auto end = ::lseek(fd_, 0, SEEK_END);
  if (end < 0) throw Error(locate(path_, 0, "cannot read region file: " + errnoText()));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(end));
  if (!bytes.empty()) readAt(fd_, bytes.data(), bytes.size(), 0);

  if (bytes.empty()) {  // new file
    writeAll(fd_, reinterpret_cast<const std::uint8_t*>(kFileMagic), kHeaderSize, 0);
    size_ = kHeaderSize;
    return;
  }
  if (bytes.size() < kHeaderSize || std::memcmp(bytes.data(), kFileMagic, kHeaderSize) != 0) {
    report(0, "not a Terrasol region file header; scanning for records anyway");
  }
  size_ = bytes.size();
  for (std::uint64_t offset = std::min<std::uint64_t>(kHeaderSize, bytes.size()); offset < bytes.size();) {
    offset = scanRecord(bytes, offset);
  }
}

std::uint64_t RegionFile::scanRecord(const std::vector<std::uint8_t>& bytes, std::uint64_t offset) {
  const RecordView r = viewRecord(bytes, offset);
  if (!r.whole) {
    const std::uint64_t next = findMagic(bytes, offset + 1);
    if (next == bytes.size()) {
      cutTornTail(bytes, offset, r);
      return bytes.size();
    }
    report(offset, r.magicOk ? "record header of " + r.name + " is corrupt"
                             : "unreadable bytes up to the next record");
    keepAside(bytes, offset, next - offset, r.magicOk ? r.label : "garbage");
    return next;
  }
  const std::uint8_t* h = &bytes[offset];
  const bool intact = get64(h + 24) == recordChecksum(h, h + kRecordHeaderSize, r.size);
  if (!intact || RegionPos::of(r.chunk) != region_) {
    // The size field may be the corrupt part, so resynchronise on the next magic rather than
    // trusting it: valid records after this one still load.
    report(offset, r.name + (intact ? " does not belong in this region" : " fails its checksum") +
                       "; it is not loaded and other chunks are");
    const std::uint64_t next = findMagic(bytes, offset + 1);
    keepAside(bytes, offset, next - offset, r.label);
    return next;
  }
  indexRecord(r.chunk, Entry{offset, r.size, get64(h + 16)});
  return offset + kRecordHeaderSize + r.size;
}

// What a kill during a save leaves: reported, kept aside, and cut off so new records follow valid ones.
void RegionFile::cutTornTail(const std::vector<std::uint8_t>& bytes, std::uint64_t offset,
                             const RecordView& r) {
  report(offset,
         "torn record at the end of the file (an interrupted save); " + r.name + " keeps its previous save");
  keepAside(bytes, offset, bytes.size() - offset, r.label + "_torn");
  size_ = offset;
  if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0) {
    throw Error(locate(path_, 0, "cannot cut off a torn record: " + errnoText()));
  }
}

// The newest record of a chunk (highest sequence number) is the one that counts.
void RegionFile::indexRecord(ChunkPos chunk, const Entry& entry) {
  auto [it, inserted] = index_.try_emplace(localIndex(chunk), entry);
  if (!inserted && entry.sequence >= it->second.sequence) {
    liveBytes_ -= kRecordHeaderSize + it->second.size;
    it->second = entry;
    inserted = true;
  }
  if (inserted) liveBytes_ += kRecordHeaderSize + entry.size;
  nextSequence_ = std::max(nextSequence_, entry.sequence + 1);
}

std::optional<std::vector<std::uint8_t>> RegionFile::read(ChunkPos chunk) const {
  const auto it = index_.find(localIndex(chunk));
  if (it == index_.end()) return std::nullopt;
  std::vector<std::uint8_t> payload(it->second.size);
  try {
    readAt(fd_, payload.data(), payload.size(), it->second.offset + kRecordHeaderSize);
  } catch (const Error& e) {
    throw Error(locate(path_, 0, "cannot read chunk: " + std::string(e.what())));
  }
  return payload;
}

void RegionFile::write(ChunkPos chunk, const std::vector<std::uint8_t>& payload) {
  if (payload.size() > kMaxPayload) throw Error(locate(path_, 0, "chunk payload too large"));
  const auto record =
      makeRecord(chunk, payload.data(), static_cast<std::uint32_t>(payload.size()), nextSequence_);
  try {
    writeAll(fd_, record.data(), record.size(), size_);
  } catch (const Error& e) {
    [[maybe_unused]] const int ignored = ::ftruncate(fd_, static_cast<off_t>(size_));  // best effort
    throw Error(locate(
        path_, 0,
        "cannot save chunk (" + std::to_string(chunk.x) + ", " + std::to_string(chunk.z) + "): " + e.what()));
  }
  const Entry entry{size_, static_cast<std::uint32_t>(payload.size()), nextSequence_++};
  auto [it, inserted] = index_.try_emplace(localIndex(chunk), entry);
  if (!inserted) {
    liveBytes_ -= kRecordHeaderSize + it->second.size;
    it->second = entry;
  }
  liveBytes_ += record.size();
  size_ += record.size();
}

void RegionFile::sync() {
  if (::fdatasync(fd_) != 0) throw Error(locate(path_, 0, "cannot flush to disk: " + errnoText()));
}

bool RegionFile::compactIfWasteful() {
  if (size_ < (1u << 20) || liveBytes_ * 2 > size_) return false;
  // Copy live records into a new file, make it durable, then atomically put it in place.
  const std::filesystem::path tmp = path_.string() + ".tmp";
  // Read-write: after the rename this descriptor is the region file, with no reopen that could fail.
  const int out = ::open(tmp.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0) throw Error(locate(tmp, 0, "cannot create: " + errnoText()));
  std::unordered_map<int, Entry> moved;
  std::uint64_t offset = kHeaderSize;
  try {
    writeAll(out, reinterpret_cast<const std::uint8_t*>(kFileMagic), kHeaderSize, 0);
    for (const auto& [local, entry] : index_) {
      std::vector<std::uint8_t> record(kRecordHeaderSize + entry.size);
      readAt(fd_, record.data(), record.size(), entry.offset);
      writeAll(out, record.data(), record.size(), offset);
      moved[local] = Entry{offset, entry.size, entry.sequence};
      offset += record.size();
    }
    if (::fsync(out) != 0) throw Error(errnoText());
  } catch (const Error& e) {
    ::close(out);
    std::filesystem::remove(tmp);
    throw Error(locate(tmp, 0, std::string("cannot compact: ") + e.what()));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path_, ec);
  if (ec) {
    ::close(out);
    std::filesystem::remove(tmp);
    throw Error(locate(path_, 0, "cannot replace with the compacted file: " + ec.message()));
  }
  syncDirectory(path_.parent_path());
  ::close(fd_);
  fd_ = out;
  index_ = std::move(moved);
  size_ = liveBytes_ = offset;
  liveBytes_ -= kHeaderSize;
  return true;
}

}  // namespace terrasol
