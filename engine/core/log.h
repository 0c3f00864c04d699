#pragma once
// Plain line logging to stderr. Thread-safe: each call writes one whole line.

#include <string_view>

namespace terrasol {

enum class LogLevel { Info, Warning, Error };

void log(LogLevel level, std::string_view message);
inline void logInfo(std::string_view message) {
  log(LogLevel::Info, message);
}
inline void logWarning(std::string_view message) {
  log(LogLevel::Warning, message);
}
inline void logError(std::string_view message) {
  log(LogLevel::Error, message);
}

}  // namespace terrasol
