#include "shaderpack/pack_conditions.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace terrasol {
namespace {

bool isWordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// A recursive-descent parser over one expression, C's precedence from || down to unary operators.
class Expression {
 public:
  Expression(std::string_view text, const PackMacros& macros, const std::string& where, int depth = 0)
      : text_(text), macros_(macros), where_(where), depth_(depth) {}

  double parse() {
    const double v = logicalOr();
    skipSpace();
    if (at_ != text_.size()) fail("unexpected '" + std::string(text_.substr(at_)) + "'");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(where_ + ": #if " + std::string(text_) + ": " + what);
  }
  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])) != 0) ++at_;
  }
  bool take(std::string_view op) {
    skipSpace();
    if (text_.compare(at_, op.size(), op) != 0) return false;
    // "<" is not the start of "<=", "!" not of "!=", "&&" not a single "&".
    if (op.size() == 1 && at_ + 1 < text_.size() && text_[at_ + 1] == '=' &&
        (op == "<" || op == ">" || op == "!"))
      return false;
    at_ += op.size();
    return true;
  }

  double logicalOr() {
    double v = logicalAnd();
    while (take("||")) {
      const double r = logicalAnd();
      v = (v != 0.0 || r != 0.0) ? 1.0 : 0.0;
    }
    return v;
  }
  double logicalAnd() {
    double v = equality();
    while (take("&&")) {
      const double r = equality();
      v = (v != 0.0 && r != 0.0) ? 1.0 : 0.0;
    }
    return v;
  }
  double equality() {
    double v = relation();
    for (;;) {
      if (take("=="))
        v = v == relation() ? 1.0 : 0.0;
      else if (take("!="))
        v = v != relation() ? 1.0 : 0.0;
      else
        return v;
    }
  }
  double relation() {
    double v = sum();
    for (;;) {
      if (take("<="))
        v = v <= sum() ? 1.0 : 0.0;
      else if (take(">="))
        v = v >= sum() ? 1.0 : 0.0;
      else if (take("<"))
        v = v < sum() ? 1.0 : 0.0;
      else if (take(">"))
        v = v > sum() ? 1.0 : 0.0;
      else
        return v;
    }
  }
  double sum() {
    double v = product();
    for (;;) {
      if (take("+"))
        v += product();
      else if (take("-"))
        v -= product();
      else
        return v;
    }
  }
  double product() {
    double v = unary();
    for (;;) {
      if (take("*")) {
        v *= unary();
      } else if (take("/") || take("%")) {
        const bool modulo = text_[at_ - 1] == '%';
        const double r = unary();
        if (r == 0.0) fail("division by zero");
        v = modulo ? std::fmod(v, r) : v / r;
      } else {
        return v;
      }
    }
  }
  double unary() {
    if (take("!")) return unary() == 0.0 ? 1.0 : 0.0;
    if (take("-")) return -unary();
    if (take("+")) return unary();
    return primary();
  }
  double primary() {
    skipSpace();
    if (take("(")) {
      const double v = logicalOr();
      if (!take(")")) fail("missing ')'");
      return v;
    }
    if (at_ >= text_.size()) fail("expression ends early");
    const std::size_t start = at_;
    while (at_ < text_.size() && (isWordChar(text_[at_]) || text_[at_] == '.')) ++at_;
    const std::string_view word = text_.substr(start, at_ - start);
    if (word.empty()) fail("unexpected '" + std::string(text_.substr(at_, 1)) + "'");
    if (std::isdigit(static_cast<unsigned char>(word[0])) != 0 || word[0] == '.') return number(word);
    if (word == "defined") {
      const bool paren = take("(");
      skipSpace();
      const std::size_t nameStart = at_;
      while (at_ < text_.size() && isWordChar(text_[at_])) ++at_;
      const std::string name(text_.substr(nameStart, at_ - nameStart));
      if (name.empty()) fail("defined without a name");
      if (paren && !take(")")) fail("missing ')' after defined(" + name);
      return macros_.defined(name) ? 1.0 : 0.0;
    }
    return macroValue(std::string(word));
  }
  double number(std::string_view word) const {
    // Integer suffixes (10u, 1L) and a float's f are C's, ignored.
    while (!word.empty() && (word.back() == 'u' || word.back() == 'U' || word.back() == 'l' ||
                             word.back() == 'L' || word.back() == 'f' || word.back() == 'F'))
      word.remove_suffix(1);
    double v = 0.0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (ec != std::errc() || end != word.data() + word.size())
      fail("'" + std::string(word) + "' is not a number");
    return v;
  }
  double macroValue(const std::string& name) const {
    if (!macros_.defined(name)) return 0.0;
    if (depth_ > 16) fail("macro '" + name + "' expands too deep");
    const std::string value = macros_.value(name);
    if (trimmed(value).empty()) return 0.0;
    return Expression(value, macros_, where_, depth_ + 1).parse();
  }

  std::string_view text_;
  const PackMacros& macros_;
  const std::string& where_;
  int depth_;
  std::size_t at_ = 0;
};

}  // namespace

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<KeptLine> propertyLines(std::string_view text, const std::string& file, PackMacros& macros) {
  std::vector<KeptLine> lines = keptLines(text, file, macros);
  std::vector<KeptLine> joined;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    KeptLine line = std::move(lines[i]);
    while (!line.text.empty() && line.text.back() == '\\' && i + 1 < lines.size()) {
      line.text.pop_back();
      line.text += lines[++i].text;
    }
    joined.push_back(std::move(line));
  }
  return joined;
}

PackMacros::PackMacros(const std::vector<ShaderDefine>& defines) {
  for (const ShaderDefine& d : defines) values_[d.name] = d.value;
}

double PackMacros::evaluate(std::string_view expression, const std::string& where) const {
  return Expression(trimmed(expression), *this, where).parse();
}

std::vector<KeptLine> keptLines(std::string_view text, const std::string& file, PackMacros& macros) {
  // Per open conditional: whether its current branch is kept, and whether any branch was.
  struct Open {
    bool keeping, taken, parentKeeps;
    int line;
  };
  std::vector<Open> open;
  const auto keeping = [&] { return open.empty() || open.back().keeping; };
  std::vector<KeptLine> kept;
  std::istringstream in{std::string(text)};
  int number = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++number;
    const std::string where = file + ":" + std::to_string(number);
    const std::string_view line = trimmed(raw);
    if (line.empty() || line[0] != '#') {
      if (keeping()) kept.push_back({number, std::string(line)});
      continue;
    }
    std::string_view rest = trimmed(line.substr(1));
    const auto nameEnd = std::find_if(rest.begin(), rest.end(), [](char c) { return !isWordChar(c); });
    const std::string_view name = rest.substr(0, static_cast<std::size_t>(nameEnd - rest.begin()));
    const std::string_view argument = trimmed(rest.substr(name.size()));
    if (name == "if" || name == "ifdef" || name == "ifndef") {
      const bool parentKeeps = keeping();
      bool holds = false;
      if (parentKeeps) {
        holds = name == "if"      ? macros.evaluate(argument, where) != 0.0
                : name == "ifdef" ? macros.defined(std::string(argument))
                                  : !macros.defined(std::string(argument));
      }
      open.push_back({parentKeeps && holds, holds, parentKeeps, number});
    } else if (name == "elif" || name == "else") {
      if (open.empty()) throw Error(where + ": #" + std::string(name) + " without #if");
      Open& o = open.back();
      const bool holds =
          !o.taken && o.parentKeeps && (name == "else" || macros.evaluate(argument, where) != 0.0);
      o.keeping = holds;
      o.taken = o.taken || holds;
    } else if (name == "endif") {
      if (open.empty()) throw Error(where + ": #endif without #if");
      open.pop_back();
    } else if (name == "define" && keeping()) {
      const auto space = argument.find_first_of(" \t");
      macros.define(std::string(argument.substr(0, space)),
                    space == std::string_view::npos ? "1" : std::string(trimmed(argument.substr(space))));
    } else if (name == "undef" && keeping()) {
      macros.undefine(std::string(argument));
    }
    // Any other line starting with '#' is a comment, as in a properties file.
  }
  if (!open.empty()) throw Error(file + ":" + std::to_string(open.back().line) + ": #if without #endif");
  return kept;
}

}  // namespace terrasol
