#pragma once
// GLSL source preprocessing: `#include "path"` resolution (each file once), `#define`s injected from
// C++ constants right after `#version`, and a line map that turns driver log positions back into
// the original `file:line`. GL-free, so it is unit-tested without a context.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace terrasol {

struct ShaderDefine {
  std::string name;
  std::string value;
};

struct SourceLocation {
  std::string file;  // path relative to the shader root, or "<defines>" for injected lines
  int line = 0;      // 1-based
};

struct PreprocessedShader {
  std::string text;
  std::vector<SourceLocation> lines;  // lines[i] is where output line i+1 came from

  // Origin of 1-based output line `line`; {"<unknown>", line} when out of range.
  SourceLocation origin(int line) const;
  // Rewrites the positions in a driver's info log (Mesa "0:12(5):", NVIDIA "0(12) :",
  // AMD/Intel "ERROR: 0:12:") as "file:line:". Lines without a position pass through unchanged.
  std::string mapLog(std::string_view log) const;
};

// The names `source` declares as plain uniforms (not blocks), in order, comments ignored. Text inside
// #if blocks counts: a declaration is there whether or not a variant's defines keep it.
std::vector<std::string> declaredUniforms(std::string_view source);

// How `#include "path"` is resolved. Terrasol's shaders: paths from the root, each file once. Shader
// packs (OptiFine, Iris): "path" from the including file's folder and "/path" from the root, every
// include expanded (packs guard their own), a file including itself through others an error, and
// at most 10 deep.
struct IncludeRules {
  bool oncePerFile = true;
  bool relativeToFile = false;
  int depthLimit = 0;  // 0: none

  static IncludeRules shaderPack() { return {false, true, 10}; }
};

class ShaderPreprocessor {
 public:
  // Returns a file's text by its root-relative path, or nothing when it does not exist.
  using FileReader = std::function<std::optional<std::string>(const std::string& path)>;

  // Reads files from `root` (normally paths::shaderDir()).
  explicit ShaderPreprocessor(std::filesystem::path root);
  // Reads files through `reader`; used by tests with in-memory sources.
  explicit ShaderPreprocessor(FileReader reader, std::string rootName = "shaders", IncludeRules rules = {});

  // Throws Error naming "file:line" for a missing file or include, a malformed directive, a
  // missing `#version`, or a `#version` inside an included file.
  PreprocessedShader process(const std::string& file, const std::vector<ShaderDefine>& defines = {}) const;

  // How files are named in messages: "<root name>/<path>".
  std::string displayName(const std::string& file) const;

 private:
  FileReader reader_;
  std::string rootName_;
  IncludeRules rules_;
};

}  // namespace terrasol
