#pragma once
// The files of one resource pack, from a folder or a .zip archive, by '/'-separated path relative to
// the pack root ("assets/minecraft/textures/block/stone.png").

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace terrasol {

class PackSource {
 public:
  // Largest file read from a pack: bigger ones are an error, not an allocation (zip bombs).
  static constexpr std::uint64_t kMaxFileBytes = 64ull << 20;

  // A folder, or a .zip file. Throws Error naming the path: missing, unreadable, not a zip, or a zip
  // entry with an absolute or ".." path.
  static std::unique_ptr<PackSource> open(const std::filesystem::path& path);
  virtual ~PackSource() = default;

  // The file's bytes, or nothing when the pack has no such file. Throws Error when it exists but
  // cannot be read or is too large.
  virtual std::optional<std::vector<std::uint8_t>> read(const std::string& path) const = 0;
  // The file's bytes; throws Error naming it when it is missing or unreadable.
  std::vector<std::uint8_t> require(const std::string& path) const {
    auto bytes = read(path);
    if (!bytes) throwMissing(path);
    return std::move(*bytes);
  }

  // Names of the files directly inside `dir` (no trailing '/'), sorted.
  virtual std::vector<std::string> list(const std::string& dir) const = 0;

  const std::filesystem::path& location() const { return location_; }
  // How messages name a file of this pack: "PACK/path" for folders, "PACK.zip!path" for zips.
  virtual std::string displayName(const std::string& path) const = 0;

 protected:
  [[noreturn]] void throwMissing(const std::string& path) const;
  explicit PackSource(std::filesystem::path location) : location_(std::move(location)) {}

 private:
  std::filesystem::path location_;
};

}  // namespace terrasol
