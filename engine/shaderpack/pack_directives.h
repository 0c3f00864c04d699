#pragma once
// What a pack program's preprocessed source tells the pipeline (OptiFine shaders.txt, Iris's
// CommentDirectiveParser and ProgramDirectives): the buffers it draws to, from `/* RENDERTARGETS:
// 0,2,11 */` or else `/* DRAWBUFFERS:0257 */` (the last of each, spaces trimmed), and its `const`
// directives (`const int shadowMapResolution = 2048;`, `const bool colortex3Clear = false;`, ...) by
// name, with their values' text. GL-free.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "assets/shader_source.h"

namespace terrasol {

inline constexpr int kPackColorBuffers = 16;  // colortex0..15
inline constexpr int kPackMaxDrawBuffers = 8;

struct ProgramDirectives {
  // The colortex buffers written, in output order; nothing when the source names none (OptiFine
  // then writes the first eight).
  std::optional<std::vector<int>> drawBuffers;
  std::map<std::string, std::string> constants;

  std::optional<double> number(const std::string& name) const;  // "2048", "-40.0", "0.5f"
  std::optional<bool> flag(const std::string& name) const;      // "true" or "false"
};

// Throws Error naming the pack's file and line (through the source's line map) for a buffer list
// that is not numbers 0..15, names a buffer twice or more than eight.
ProgramDirectives parseDirectives(const PreprocessedShader& source);

}  // namespace terrasol
