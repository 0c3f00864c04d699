#pragma once
// Errors at load boundaries: every message names the file, the place in it and what is wrong.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace terrasol {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "FILE:LINE: what" (line omitted when 0), the form compilers use, so editors can jump to it.
std::string locate(const std::filesystem::path& file, int line, std::string_view what);

// Reads a whole file; throws Error naming the file when it cannot.
std::string readTextFile(const std::filesystem::path& file);
// Writes FILE.tmp, syncs it and renames it over FILE, so a crash leaves the old or the new file, never
// half of one. Throws Error naming the file.
void writeFileAtomically(const std::filesystem::path& file, std::string_view text);
// Reads exactly `size` bytes at `offset` of an open file (pread, retried when interrupted), from any
// thread. Throws Error saying what went wrong ("unexpected end of file"); the caller names the file.
void readAt(int fd, std::uint8_t* data, std::size_t size, std::uint64_t offset);

}  // namespace terrasol
