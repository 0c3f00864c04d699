#include "minecraft/anvil_region.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "minecraft/chunk_compression.h"

namespace terrasol {
namespace {

constexpr std::uint8_t kExternalFlag = 128;

std::uint32_t bigU32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// A chunk too large for its region: the whole .mcc file is its compressed data.
std::vector<std::uint8_t> readExternal(const std::filesystem::path& file, const std::string& what) {
  const std::string name = file.filename().string();
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw Error(what + ": kept in " + name + ", which cannot be read");
  if (size > kMaxChunkBytes)
    throw Error(what + ": " + name + " is over " + std::to_string(kMaxChunkBytes >> 20) + " MiB");
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint8_t> data(size);
  if (!in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(size)))
    throw Error(what + ": cannot read " + name);
  return data;
}

}  // namespace

AnvilRegion::AnvilRegion(std::filesystem::path path, int regionX, int regionZ)
    : path_(std::move(path)), regionX_(regionX), regionZ_(regionZ) {
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw Error(path_.string() + ": cannot open (" + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    ::close(fd_);
    throw Error(path_.string() + ": cannot read its size");
  }
  size_ = static_cast<std::uint64_t>(st.st_size);
  try {
    readHeader();
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

AnvilRegion::~AnvilRegion() {
  if (fd_ >= 0) ::close(fd_);
}

std::string AnvilRegion::describe(ChunkPos c) const {
  return path_.filename().string() + " chunk (" + std::to_string(c.x) + ", " + std::to_string(c.z) + ")";
}

std::vector<std::uint8_t> AnvilRegion::readBytes(std::uint64_t offset, std::size_t size,
                                                 const std::string& what) const {
  std::vector<std::uint8_t> bytes(size);
  try {
    readAt(fd_, bytes.data(), size, offset);
  } catch (const Error& e) {
    throw Error(what + ": cannot read " + std::to_string(size) + " bytes at " + std::to_string(offset) +
                " (" + e.what() + ")");
  }
  return bytes;
}

void AnvilRegion::readHeader() {
  if (size_ == 0) return;  // an empty region, as Minecraft leaves some
  constexpr std::size_t kHeaderBytes = 2 * kSectorBytes;
  if (size_ < kHeaderBytes)
    throw Error(path_.string() + ": " + std::to_string(size_) + " bytes, shorter than the 8 KiB header");
  const std::vector<std::uint8_t> header = readBytes(0, kHeaderBytes, path_.string());
  const std::uint64_t fileSectors = (size_ + kSectorBytes - 1) / kSectorBytes;
  for (int i = 0; i < kSlots; ++i) {
    const std::uint32_t location = bigU32(header.data() + 4 * i);
    if (location == 0) continue;
    const Slot slot{location >> 8, location & 0xFF};
    const std::string where = describe(chunkOf(i));
    if (slot.sectors == 0 || slot.sector < 2) {
      problems_.push_back(where + ": header points at sector " + std::to_string(slot.sector) + " (count " +
                          std::to_string(slot.sectors) + "), inside the header; left out");
    } else if (slot.sector + slot.sectors > fileSectors) {
      problems_.push_back(where + ": sectors " + std::to_string(slot.sector) + ".." +
                          std::to_string(slot.sector + slot.sectors - 1) + " run past the end of the file (" +
                          std::to_string(fileSectors) + " sectors); left out");
    } else {
      slots_[i] = slot;
    }
  }
  // Two chunks claiming one sector: both are suspect, so both are left out.
  std::vector<int> order;
  for (int i = 0; i < kSlots; ++i)
    if (slots_[i].sectors) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return slots_[a].sector < slots_[b].sector; });
  std::vector<int> overlapping;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Slot& before = slots_[order[k - 1]];
    if (before.sector + before.sectors > slots_[order[k]].sector) {
      overlapping.push_back(order[k - 1]);
      overlapping.push_back(order[k]);
      problems_.push_back(describe(chunkOf(order[k])) + ": its sectors overlap those of " +
                          describe(chunkOf(order[k - 1])) + "; both left out");
    }
  }
  for (const int i : overlapping) slots_[i] = {};
}

std::vector<ChunkPos> AnvilRegion::chunks() const {
  std::vector<ChunkPos> out;
  for (int i = 0; i < kSlots; ++i)
    if (slots_[i].sectors) out.push_back(chunkOf(i));
  return out;
}

std::optional<std::vector<std::uint8_t>> AnvilRegion::read(ChunkPos chunk) const {
  const Slot& slot = slots_[slotOf(chunk)];
  if (slot.sectors == 0) return std::nullopt;
  const std::string what = describe(chunk);
  const std::uint64_t start = std::uint64_t(slot.sector) * kSectorBytes;
  const std::size_t span = std::size_t(slot.sectors) * kSectorBytes;
  std::vector<std::uint8_t> bytes = readBytes(start, std::min<std::uint64_t>(span, size_ - start), what);
  if (bytes.size() < 5) throw Error(what + ": shorter than its 5-byte chunk header");
  const std::uint32_t length = bigU32(bytes.data());
  if (length == 0 || length > bytes.size() - 4)
    throw Error(what + ": length " + std::to_string(length) + " does not fit its " +
                std::to_string(slot.sectors) + " sectors");
  const std::uint8_t type = bytes[4];
  const auto compression = static_cast<ChunkCompression>(type & ~kExternalFlag);
  if (compression < ChunkCompression::Gzip || compression > ChunkCompression::Lz4)
    throw Error(what + ": unknown compression type " + std::to_string(type));
  if (type & kExternalFlag) {
    const auto external =
        path_.parent_path() / ("c." + std::to_string(chunk.x) + "." + std::to_string(chunk.z) + ".mcc");
    const std::vector<std::uint8_t> data = readExternal(external, what);
    return decompressChunk(compression, data, what + " (" + external.filename().string() + ")");
  }
  return decompressChunk(compression, std::span(bytes).subspan(5, length - 1), what);
}

}  // namespace terrasol
