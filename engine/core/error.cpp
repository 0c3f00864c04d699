#include "core/error.h"

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

}  // namespace terrasol
