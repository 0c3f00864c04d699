#include "assets/shader_source.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"

namespace terrasol {
namespace {

std::string_view trimLeft(std::string_view s) {
  const auto start = s.find_first_not_of(" \t");
  return start == std::string_view::npos ? std::string_view{} : s.substr(start);
}

// "#  include" counts as an include, like the C preprocessor; returns the directive name or "".
std::string_view directive(std::string_view line) {
  line = trimLeft(line);
  if (line.empty() || line[0] != '#') return {};
  line = trimLeft(line.substr(1));
  const auto end = line.find_first_of(" \t\r");
  return line.substr(0, end);
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

// Lexically normalises an include path; rejects absolute paths and escapes above the root.
std::optional<std::string> normalise(const std::string& path) {
  const std::filesystem::path p = std::filesystem::path(path).lexically_normal();
  if (p.empty() || p.is_absolute() || *p.begin() == "..") return std::nullopt;
  return p.generic_string();
}

struct Expander {
  const ShaderPreprocessor& pre;
  const ShaderPreprocessor::FileReader& reader;
  const IncludeRules& rules;
  PreprocessedShader out;
  std::set<std::string> included;
  std::vector<std::string> open;  // the files being expanded, outermost first

  void emit(const std::string& text, std::string file, int line) {
    out.text += text;
    out.text += '\n';
    out.lines.push_back({std::move(file), line});
  }

  std::string includeTarget(const std::string& file, int line, std::string_view text) {
    const auto open = text.find('"');
    const auto close = open == std::string_view::npos ? open : text.find('"', open + 1);
    if (close == std::string_view::npos || close == open + 1) {
      throw Error(locate(pre.displayName(file), line, "malformed #include, expected #include \"path\""));
    }
    const std::string raw(text.substr(open + 1, close - open - 1));
    std::string from = raw;
    if (rules.relativeToFile)
      from = raw.starts_with('/') ? raw.substr(1)
                                  : std::filesystem::path(file).parent_path().append(raw).generic_string();
    const auto path = normalise(from);
    if (!path)
      throw Error(locate(pre.displayName(file), line, "include path '" + raw + "' leaves the shader root"));
    return *path;
  }

  void expand(const std::string& file, bool isMain, const std::vector<ShaderDefine>& defines,
              const std::string& includedFrom, int includedAt) {
    const auto where = [&](const std::string& what) {
      return includedFrom.empty() ? what : locate(pre.displayName(includedFrom), includedAt, what);
    };
    if (std::find(open.begin(), open.end(), file) != open.end())
      throw Error(where("'" + pre.displayName(file) + "' includes itself"));
    if (rules.depthLimit > 0 && static_cast<int>(open.size()) > rules.depthLimit)
      throw Error(where("includes nested deeper than " + std::to_string(rules.depthLimit)));
    included.insert(file);
    const auto text = reader(file);
    if (!text) throw Error(where("cannot find shader file '" + pre.displayName(file) + "'"));
    open.push_back(file);
    const auto lines = splitLines(*text);
    bool sawVersion = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const int lineNo = static_cast<int>(i) + 1;
      const std::string_view name = directive(lines[i]);
      if (name == "version") {
        if (!isMain) throw Error(locate(pre.displayName(file), lineNo, "#version in an included file"));
        if (sawVersion) throw Error(locate(pre.displayName(file), lineNo, "second #version"));
        sawVersion = true;
        emit(lines[i], file, lineNo);
        for (const auto& d : defines) emit("#define " + d.name + " " + d.value, "<defines>", 0);
      } else if (name == "include") {
        if (isMain && !sawVersion)
          throw Error(locate(pre.displayName(file), lineNo, "#include before #version"));
        const std::string target = includeTarget(file, lineNo, lines[i]);
        if (!rules.oncePerFile || !included.contains(target)) expand(target, false, defines, file, lineNo);
      } else {
        emit(lines[i], file, lineNo);
      }
    }
    if (isMain && !sawVersion) throw Error(locate(pre.displayName(file), 1, "missing #version"));
    open.pop_back();
  }
};

}  // namespace

std::vector<std::string> declaredUniforms(std::string_view source) {
  // Comments become a space; one pass, as every program's sources are read at link (a regex took a
  // tenth of the renderer's start).
  std::string code;
  code.reserve(source.size());
  for (std::size_t i = 0; i < source.size();) {
    if (source.compare(i, 2, "//") == 0) {
      i = std::min(source.find('\n', i), source.size());
    } else if (source.compare(i, 2, "/*") == 0) {
      const std::size_t close = source.find("*/", i + 2);
      i = close == std::string_view::npos ? source.size() : close + 2;
      code += ' ';
    } else {
      code += source[i++];
    }
  }
  const auto isWord = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  const auto skipSpace = [&](std::size_t i) {
    while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i])) != 0) ++i;
    return i;
  };
  const auto wordEnd = [&](std::size_t i) {
    while (i < code.size() && isWord(code[i])) ++i;
    return i;
  };
  // "uniform [precision] <type> a, b[N];": the names between the type and the semicolon (a block,
  // "uniform Name { ... }", has none).
  std::vector<std::string> names;
  constexpr std::string_view kUniform = "uniform";
  for (std::size_t at = code.find(kUniform); at != std::string::npos; at = code.find(kUniform, at + 1)) {
    const std::size_t after = at + kUniform.size();
    if ((at > 0 && isWord(code[at - 1])) || after >= code.size() || isWord(code[after])) continue;
    const std::size_t end = code.find_first_of(";{", after);
    if (end == std::string::npos || code[end] == '{') continue;
    std::size_t i = skipSpace(after);
    std::size_t typeEnd = wordEnd(i);
    const std::string_view first(code.data() + i, typeEnd - i);
    if (first == "lowp" || first == "mediump" || first == "highp") typeEnd = wordEnd(skipSpace(typeEnd));
    int depth = 0;
    bool expectName = true;
    for (i = typeEnd; i < end; ++i) {
      const char c = code[i];
      if (c == '[') ++depth;
      if (c == ']') --depth;
      if (c == ',' && depth == 0) expectName = true;
      if (expectName && isWord(c)) {
        const std::size_t e = wordEnd(i);
        names.emplace_back(code, i, e - i);
        expectName = false;
        i = e - 1;
      }
    }
  }
  return names;
}

SourceLocation PreprocessedShader::origin(int line) const {
  if (line < 1 || line > static_cast<int>(lines.size())) return {"<unknown>", line};
  return lines[static_cast<std::size_t>(line) - 1];
}

std::string PreprocessedShader::mapLog(std::string_view log) const {
  // Group 1: prefix kept as is; group 2: the output line number; the rest of the position is dropped.
  static const std::regex kPositions[] = {
      std::regex(R"(^()\d+:(\d+)\(\d+\):\s*)"),                // Mesa:    0:12(5): error: ...
      std::regex(R"(^()\d+\((\d+)\)\s*:\s*)"),                 // NVIDIA:  0(12) : error C1008: ...
      std::regex(R"(^(ERROR:\s*|WARNING:\s*)\d+:(\d+):\s*)"),  // AMD/Intel: ERROR: 0:12: ...
  };
  std::string result;
  std::istringstream in{std::string(log)};
  for (std::string line; std::getline(in, line);) {
    for (const auto& re : kPositions) {
      std::smatch m;
      if (std::regex_search(line, m, re)) {
        const SourceLocation where = origin(std::stoi(m[2].str()));
        line = where.file + ":" + std::to_string(where.line) + ": " + m[1].str() + m.suffix().str();
        break;
      }
    }
    result += line;
    result += '\n';
  }
  return result;
}

ShaderPreprocessor::ShaderPreprocessor(std::filesystem::path root)
    : reader_([root](const std::string& path) -> std::optional<std::string> {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(root / path, ec)) return std::nullopt;
        return readTextFile(root / path);
      }),
      rootName_(root.filename().string()) {}

ShaderPreprocessor::ShaderPreprocessor(FileReader reader, std::string rootName, IncludeRules rules)
    : reader_(std::move(reader)), rootName_(std::move(rootName)), rules_(rules) {}

std::string ShaderPreprocessor::displayName(const std::string& file) const {
  return rootName_ + "/" + file;
}

PreprocessedShader ShaderPreprocessor::process(const std::string& file,
                                               const std::vector<ShaderDefine>& defines) const {
  const auto path = normalise(file);
  if (!path) throw Error("shader path '" + file + "' leaves the shader root");
  Expander expander{*this, reader_, rules_, {}, {}, {}};
  expander.expand(*path, true, defines, "", 0);
  for (auto& loc : expander.out.lines) {
    if (loc.file != "<defines>") loc.file = displayName(loc.file);
  }
  return std::move(expander.out);
}

}  // namespace terrasol
