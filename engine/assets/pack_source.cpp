#include "assets/pack_source.h"

#include <zip.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

#include "core/error.h"

namespace terrasol {
namespace {

// Rejects paths that could leave the pack: absolute, drive letters, "..", empty components.
bool safeRelative(const std::string& path) {
  if (path.empty() || path[0] == '/' || path[0] == '\\' || path.find(':') != std::string::npos) return false;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find_first_of("/\\", start), path.size());
    const std::string part = path.substr(start, end - start);
    if (part == "..") return false;
    if (part.empty() && end != path.size()) return false;
    start = end + 1;
  }
  return true;
}

class FolderSource final : public PackSource {
 public:
  explicit FolderSource(std::filesystem::path root) : PackSource(std::move(root)) {}

  std::optional<std::vector<std::uint8_t>> read(const std::string& path) const override {
    if (!safeRelative(path)) return std::nullopt;
    const auto file = location() / path;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    const auto size = std::filesystem::file_size(file, ec);
    if (ec) throw Error(locate(file, 0, "cannot read: " + ec.message()));
    if (size > kMaxFileBytes)
      throw Error(locate(file, 0, "file too large (" + std::to_string(size) + " bytes)"));
    std::ifstream in(file, std::ios::binary);
    std::vector<std::uint8_t> bytes(size);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    if (!in) throw Error(locate(file, 0, "cannot read"));
    return bytes;
  }

  std::vector<std::string> list(const std::string& dir) const override {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(location() / dir, ec)) {
      if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  std::string displayName(const std::string& path) const override { return (location() / path).string(); }
};

class ZipSource final : public PackSource {
 public:
  explicit ZipSource(std::filesystem::path file) : PackSource(std::move(file)) {
    int error = 0;
    archive_ = zip_open(location().c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &error);
    if (!archive_) {
      zip_error_t e;
      zip_error_init_with_code(&e, error);
      const std::string why = zip_error_strerror(&e);
      zip_error_fini(&e);
      throw Error(locate(location(), 0, "cannot open zip: " + why));
    }
    const zip_int64_t count = zip_get_num_entries(archive_, 0);
    for (zip_int64_t i = 0; i < count; ++i) {
      const char* name = zip_get_name(archive_, static_cast<zip_uint64_t>(i), ZIP_FL_ENC_GUESS);
      if (!name) continue;
      std::string path = name;
      if (!path.empty() && path.back() == '/') continue;  // directory entry
      if (!safeRelative(path)) {
        zip_discard(archive_);
        throw Error(location().string() + "!" + path + ": zip entry path is absolute or leaves the pack");
      }
      entries_[path] = static_cast<zip_uint64_t>(i);
    }
    // Packs zipped with a top folder ("MyPack/pack.mcmeta") are read from inside that folder.
    if (!entries_.contains("pack.mcmeta")) {
      for (const auto& [path, index] : entries_) {
        const auto slash = path.find('/');
        if (slash != std::string::npos && path.substr(slash + 1) == "pack.mcmeta") {
          prefix_ = path.substr(0, slash + 1);
          break;
        }
      }
    }
  }
  ~ZipSource() override { zip_discard(archive_); }
  ZipSource(const ZipSource&) = delete;
  ZipSource& operator=(const ZipSource&) = delete;

  std::optional<std::vector<std::uint8_t>> read(const std::string& path) const override {
    const auto it = entries_.find(prefix_ + path);
    if (it == entries_.end()) return std::nullopt;
    zip_stat_t stat;
    if (zip_stat_index(archive_, it->second, 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE)) {
      throw Error(displayName(path) + ": cannot read zip entry");
    }
    if (stat.size > kMaxFileBytes)
      throw Error(displayName(path) + ": file too large (" + std::to_string(stat.size) + " bytes)");
    zip_file_t* file = zip_fopen_index(archive_, it->second, 0);
    if (!file) throw Error(displayName(path) + ": cannot open zip entry: " + zip_strerror(archive_));
    std::vector<std::uint8_t> bytes(stat.size);
    const zip_int64_t n = zip_fread(file, bytes.data(), stat.size);
    zip_fclose(file);
    if (n < 0 || static_cast<zip_uint64_t>(n) != stat.size)
      throw Error(displayName(path) + ": corrupt zip entry");
    return bytes;
  }

  std::vector<std::string> list(const std::string& dir) const override {
    const std::string prefix = prefix_ + dir + "/";
    std::vector<std::string> names;
    for (auto it = entries_.lower_bound(prefix); it != entries_.end() && it->first.starts_with(prefix);
         ++it) {
      const std::string rest = it->first.substr(prefix.size());
      if (rest.find('/') == std::string::npos) names.push_back(rest);
    }
    return names;
  }

  std::string displayName(const std::string& path) const override {
    return location().string() + "!" + prefix_ + path;
  }

 private:
  zip_t* archive_ = nullptr;
  std::map<std::string, zip_uint64_t> entries_;
  std::string prefix_;
};

}  // namespace

void PackSource::throwMissing(const std::string& path) const {
  throw Error(displayName(path) + ": cannot be read (missing, or a name that leaves the pack)");
}

std::unique_ptr<PackSource> PackSource::open(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return std::make_unique<FolderSource>(path);
  if (std::filesystem::is_regular_file(path, ec)) return std::make_unique<ZipSource>(path);
  throw Error(locate(path, 0, "no such resource pack (expected a folder or a .zip file)"));
}

}  // namespace terrasol
