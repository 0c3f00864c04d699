#include "core/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace terrasol {

std::string locate(const std::filesystem::path& file, int line, std::string_view what) {
  std::string out = file.string();
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
  }
  out += ": ";
  out += what;
  return out;
}

std::string readTextFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(locate(file, 0, "cannot open file"));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(locate(file, 0, "read failed"));
  return std::move(text).str();
}

void writeFileAtomically(const std::filesystem::path& file, std::string_view text) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error(locate(tmp, 0, "cannot create"));
  const bool ok =
      ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok) throw Error(locate(tmp, 0, "cannot write"));
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) throw Error(locate(file, 0, "cannot replace: " + ec.message()));
}

void readAt(int fd, std::uint8_t* data, std::size_t size, std::uint64_t offset) {
  while (size > 0) {
    const ssize_t n = ::pread(fd, data, size, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(n == 0 ? "unexpected end of file" : std::strerror(errno));
    data += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<std::uint64_t>(n);
  }
}

}  // namespace terrasol
