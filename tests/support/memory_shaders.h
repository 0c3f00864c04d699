#pragma once
// A ShaderPreprocessor over in-memory files, for tests that need exact, small shader sources.

#include <map>
#include <string>

#include "assets/shader_source.h"

namespace terrasol::testing {

inline ShaderPreprocessor memoryShaders(std::map<std::string, std::string> files) {
  return ShaderPreprocessor(
      [files = std::move(files)](const std::string& path) -> std::optional<std::string> {
        const auto it = files.find(path);
        return it == files.end() ? std::nullopt : std::optional(it->second);
      });
}

}  // namespace terrasol::testing
