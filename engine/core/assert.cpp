#include "core/assert.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace terrasol::detail {

void assertionFailed(const char* file, int line, const char* condition, std::string_view message) {
  std::string text = std::string(file) + ":" + std::to_string(line) + ": assertion failed: " + condition;
  if (!message.empty()) text.append(": ").append(message);
  text += '\n';
  std::fwrite(text.data(), 1, text.size(), stderr);  // one write: whole beside other threads' lines
  std::fflush(stderr);
  std::abort();
}

}  // namespace terrasol::detail
