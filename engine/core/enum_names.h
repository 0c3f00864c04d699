#pragma once
// The names an enum's values have in files, in the enum's order: one table per enum serves parsing,
// writing and menus, so a name cannot drift between them, and a bad name is answered with the valid
// ones. An empty name marks a value files cannot name (a rule's "none", meaning the key is absent).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/error.h"

namespace terrasol {

template <class E, std::size_t N>
struct EnumNames {
  std::array<std::string_view, N> names;  // names[i] names E(i)

  constexpr std::string_view nameOf(E value) const { return names[static_cast<std::size_t>(value)]; }

  constexpr std::optional<E> find(std::string_view name) const {
    for (std::size_t i = 0; i < N; ++i) {
      if (!name.empty() && names[i] == name) return static_cast<E>(i);
    }
    return std::nullopt;
  }

  // "\"a\", \"b\", \"c\"": the names files may use.
  std::string list() const {
    std::string out;
    for (std::string_view n : names) {
      if (n.empty()) continue;
      if (!out.empty()) out += ", ";
      out.append("\"").append(n).append("\"");
    }
    return out;
  }

  // Throws Error "WHAT: unknown "x"; expected one of ..." for a name not in the table.
  E parse(std::string_view name, std::string_view what) const {
    if (const std::optional<E> value = find(name)) return *value;
    std::string message(what);
    message.append(": unknown \"").append(name).append("\"; expected one of ").append(list());
    throw Error(message);
  }

  // Positional access for menus and loops over every value.
  constexpr std::size_t size() const { return N; }
  constexpr std::string_view operator[](std::size_t i) const { return names[i]; }
  constexpr operator std::span<const std::string_view>() const { return names; }
};

template <class E, std::size_t N>
constexpr std::string_view nameOf(E value, const EnumNames<E, N>& names) {
  return names.nameOf(value);
}

}  // namespace terrasol
