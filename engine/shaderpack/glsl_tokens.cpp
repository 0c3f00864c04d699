#include "shaderpack/glsl_tokens.h"

#include <cctype>

namespace terrasol {
namespace {

bool identStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool identChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace

std::vector<GlslToken> tokenizeGlsl(std::string_view s) {
  std::vector<GlslToken> out;
  int line = 1;
  bool lineStart = true;  // only spaces so far on this line
  bool directive = false;
  std::size_t i = 0;
  const auto push = [&](GlslTokenKind kind, std::size_t end) {
    GlslToken t{kind, std::string(s.substr(i, end - i)), line, directive};
    for (char c : t.text) line += c == '\n';
    out.push_back(std::move(t));
    i = end;
  };
  while (i < s.size()) {
    const char c = s[i];
    if (c == '\n') {
      // A backslash before the newline continues a directive.
      const bool continued = directive && !out.empty() && out.back().is("\\");
      push(GlslTokenKind::Newline, i + 1);
      directive = continued;
      lineStart = !continued;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      std::size_t e = i;
      while (e < s.size() && (s[e] == ' ' || s[e] == '\t' || s[e] == '\r' || s[e] == '\f' || s[e] == '\v'))
        ++e;
      push(GlslTokenKind::Space, e);
      continue;
    }
    if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
      push(GlslTokenKind::Comment, std::min(s.find('\n', i), s.size()));
      continue;
    }
    if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
      const std::size_t close = s.find("*/", i + 2);
      push(GlslTokenKind::Comment, close == std::string_view::npos ? s.size() : close + 2);
      continue;
    }
    if (c == '#' && lineStart) directive = true;
    lineStart = false;
    if (identStart(c)) {
      std::size_t e = i;
      while (e < s.size() && identChar(s[e])) ++e;
      push(GlslTokenKind::Identifier, e);
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      // Digits, letters (suffixes, hex, exponents) and points; a sign right after an exponent.
      std::size_t e = i;
      while (e < s.size()) {
        if (identChar(s[e]) || s[e] == '.') {
          ++e;
        } else if ((s[e] == '+' || s[e] == '-') && (s[e - 1] == 'e' || s[e - 1] == 'E') &&
                   !(s[i] == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X'))) {
          ++e;
        } else {
          break;
        }
      }
      push(GlslTokenKind::Number, e);
    } else {
      push(GlslTokenKind::Punct, i + 1);
    }
  }
  return out;
}

std::string joinTokens(const std::vector<GlslToken>& tokens) {
  std::string out;
  for (const GlslToken& t : tokens) out += t.text;
  return out;
}

}  // namespace terrasol
