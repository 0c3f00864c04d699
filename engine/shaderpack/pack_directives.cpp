#include "shaderpack/pack_directives.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <regex>

#include "core/error.h"
#include "shaderpack/pack_conditions.h"

namespace terrasol {
namespace {

// A /* KEY: value */ comment's value and where it starts, the last one with this key.
struct Directive {
  std::string value;
  std::size_t at = 0;
};

std::optional<Directive> lastDirective(const std::string& text, std::string_view key) {
  std::optional<Directive> found;
  for (std::size_t open = text.find("/*"); open != std::string::npos; open = text.find("/*", open + 2)) {
    const std::size_t close = text.find("*/", open + 2);
    const std::string_view body = trimmed(std::string_view(text).substr(open + 2, close - open - 2));
    if (body.starts_with(key) && trimmed(body.substr(key.size())).starts_with(':'))
      found = Directive{std::string(trimmed(trimmed(body.substr(key.size())).substr(1))), open};
    if (close == std::string::npos) break;
  }
  return found;
}

// Line comments become spaces. Block comments stay: packs wrap the directives GLSL would not compile
// in them (`/* const int colortex0Format = RGBA16F; */`), and OptiFine and Iris read them there.
std::string withoutLineComments(const std::string& text) {
  std::string out = text;
  for (std::size_t i = 0; i < out.size();) {
    if (out.compare(i, 2, "//") == 0) {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
    } else if (out.compare(i, 2, "/*") == 0) {
      i = std::min(out.find("*/", i + 2), out.size());
    } else {
      ++i;
    }
  }
  return out;
}

}  // namespace

std::optional<double> ProgramDirectives::number(const std::string& name) const {
  const auto found = constants.find(name);
  if (found == constants.end()) return std::nullopt;
  std::string_view text = found->second;
  if (!text.empty() && (text.back() == 'f' || text.back() == 'F')) text.remove_suffix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

std::optional<bool> ProgramDirectives::flag(const std::string& name) const {
  const auto found = constants.find(name);
  if (found == constants.end() || (found->second != "true" && found->second != "false")) return std::nullopt;
  return found->second == "true";
}

ProgramDirectives parseDirectives(const PreprocessedShader& source) {
  ProgramDirectives d;
  const std::string& text = source.text;
  const auto lineOf = [&](std::size_t offset) {
    return static_cast<int>(
               std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n')) +
           1;
  };
  std::optional<Directive> targets = lastDirective(text, "RENDERTARGETS");
  const bool commas = targets.has_value();
  if (!targets) targets = lastDirective(text, "DRAWBUFFERS");
  if (targets) {
    const SourceLocation where = source.origin(lineOf(targets->at));
    const auto fail = [&](const std::string& what) {
      throw Error(where.file + ":" + std::to_string(where.line) + ": " +
                  (commas ? "RENDERTARGETS" : "DRAWBUFFERS") + " '" + targets->value + "': " + what);
    };
    std::vector<int> buffers;
    if (commas) {
      std::size_t start = 0;
      for (std::size_t i = 0; i <= targets->value.size(); ++i) {
        if (i < targets->value.size() && targets->value[i] != ',') continue;
        const std::string_view item = trimmed(std::string_view(targets->value).substr(start, i - start));
        int b = -1;
        const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), b);
        if (item.empty() || ec != std::errc() || end != item.data() + item.size())
          fail("expected numbers and commas");
        buffers.push_back(b);
        start = i + 1;
      }
    } else {
      for (const char c : targets->value) {
        if (std::isdigit(static_cast<unsigned char>(c)) == 0) fail("expected digits 0 to 9");
        buffers.push_back(c - '0');
      }
    }
    if (buffers.empty() || buffers.size() > kPackMaxDrawBuffers) fail("expected 1 to 8 buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      if (buffers[i] < 0 || buffers[i] >= kPackColorBuffers)
        fail("colortex" + std::to_string(buffers[i]) + " does not exist");
      if (std::find(buffers.begin(), buffers.begin() + static_cast<std::ptrdiff_t>(i), buffers[i]) !=
          buffers.begin() + static_cast<std::ptrdiff_t>(i))
        fail("colortex" + std::to_string(buffers[i]) + " named twice");
    }
    d.drawBuffers = std::move(buffers);
  }
  static const std::regex kConst(R"(\bconst\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+(\w+)\s*=\s*([^;]+);)");
  const std::string code = withoutLineComments(text);
  for (auto it = std::sregex_iterator(code.begin(), code.end(), kConst); it != std::sregex_iterator(); ++it)
    d.constants[(*it)[1].str()] = std::string(trimmed((*it)[2].str()));
  return d;
}

}  // namespace terrasol
