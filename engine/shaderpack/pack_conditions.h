#pragma once
// The C preprocessor's conditionals as shader packs use them in `.properties` files (OptiFine allows
// `#if`, `#ifdef`, `#ifndef`, `#elif`, `#else`, `#endif`, `#define` and `#undef` there): the lines a
// file keeps for the pack's macros. `#if` expressions take integers and decimals, macros (an unknown
// name is 0, as in C), `defined(NAME)`, `!`, unary `-`, `* / %`, `+ -`, comparisons, `== !=`, `&&`
// and `||`, with C's precedence. GL-free.

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "assets/shader_source.h"

namespace terrasol {

class PackMacros {
 public:
  PackMacros() = default;
  explicit PackMacros(const std::vector<ShaderDefine>& defines);

  void define(const std::string& name, const std::string& value = "1") { values_[name] = value; }
  void undefine(const std::string& name) { values_.erase(name); }
  bool defined(const std::string& name) const { return values_.contains(name); }
  // A defined macro's value ("" for none).
  std::string value(const std::string& name) const {
    const auto found = values_.find(name);
    return found == values_.end() ? std::string() : found->second;
  }

  // The value of an `#if` expression; throws Error naming `where` (a file and line) when it is
  // malformed.
  double evaluate(std::string_view expression, const std::string& where) const;

 private:
  std::map<std::string, std::string> values_;
};

// A line a conditional keeps, with its 1-based number in the file.
struct KeptLine {
  int number = 0;
  std::string text;
};

// The lines of `text` that the conditionals keep, trimmed, directives taken out; `#define` and
// `#undef` change `macros` as they are met. Throws Error naming `file` and the line for an unbalanced
// or malformed conditional.
std::vector<KeptLine> keptLines(std::string_view text, const std::string& file, PackMacros& macros);
// The same, with a line ending in `\` joined to the next as Java's Properties joins them (the next
// line's leading spaces dropped), numbered by its first line: a `.properties` file's entries.
std::vector<KeptLine> propertyLines(std::string_view text, const std::string& file, PackMacros& macros);

// `s` without leading and trailing spaces, tabs and carriage returns.
std::string_view trimmed(std::string_view s);

}  // namespace terrasol
