#include "core/log.h"

#include <cstdio>
#include <string>

namespace terrasol {

void log(LogLevel level, std::string_view message) {
  const char* tag = level == LogLevel::Info ? "info" : level == LogLevel::Warning ? "warning" : "error";
  std::string line = "terrasol: ";
  line += tag;
  line += ": ";
  line += message;
  line += '\n';
  std::fwrite(line.data(), 1, line.size(), stderr);  // one write per line keeps threads from interleaving
}

}  // namespace terrasol
