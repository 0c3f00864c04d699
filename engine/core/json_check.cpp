#include "core/json_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/paths.h"

namespace terrasol::json_check {
namespace {

constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

std::string describe(const json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return join({"an array of ", std::to_string(value.size())});
  std::string text = value.dump();
  if (text.size() > 40) {
    text.resize(37);
    text += "...";
  }
  return text;
}

std::string quotedList(std::span<const std::string_view> names) {
  std::string list;
  for (std::string_view name : names) list += join({list.empty() ? "" : ", ", "\"", name, "\""});
  return list;
}

// Integers and floats with no fraction (1e9 is a float to nlohmann) that fit in int64.
std::optional<std::int64_t> asWhole(const json& value) {
  if (value.is_number_unsigned()) {
    const std::uint64_t u = value.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(kMaxInt64)) return std::nullopt;
    return static_cast<std::int64_t>(u);
  }
  if (value.is_number_integer()) return value.get<std::int64_t>();
  if (!value.is_number_float()) return std::nullopt;
  const double d = value.get<double>();
  if (std::trunc(d) != d || std::abs(d) >= 0x1p63) return std::nullopt;
  return static_cast<std::int64_t>(d);
}

std::string formatNumber(double d) {
  std::ostringstream out;
  out << d;
  return out.str();
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1, column 2: " prefix.
std::string jsonDetail(const json::exception& e) {
  std::string_view what = e.what();
  const std::size_t bracket = what.find("] ");
  if (bracket != std::string_view::npos) what.remove_prefix(bracket + 2);
  const std::size_t column = what.find("column ");
  const std::size_t colon = what.find(": ", column == std::string_view::npos ? 0 : column);
  if (what.starts_with("parse error") && colon != std::string_view::npos) what.remove_prefix(colon + 2);
  return std::string(what);
}

// "FILE:LINE:COLUMN" (or "line L, column C" with no file) from nlohmann's 1-based byte index of the last
// character it read.
std::string syntaxPlace(const path& file, std::string_view text, std::size_t byte) {
  const std::string_view before = text.substr(0, std::min(byte == 0 ? 0 : byte - 1, text.size()));
  const std::size_t lastNewline = before.rfind('\n');
  const std::size_t column = lastNewline == std::string_view::npos ? byte : byte - lastNewline - 1;
  const std::string line = std::to_string(std::count(before.begin(), before.end(), '\n') + 1);
  if (file.empty()) return join({"line ", line, ", column ", std::to_string(column)});
  return join({file.string(), ":", line, ":", std::to_string(column)});
}

}  // namespace

std::string join(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view part : parts) out += part;
  return out;
}

std::string member(const std::string& parent, std::string_view name) {
  return parent.empty() ? std::string(name) : join({parent, ".", name});
}

std::string element(const std::string& parent, std::size_t index) {
  return join({parent, "[", std::to_string(index), "]"});
}

[[noreturn]] void fail(const std::string& key, std::string_view what) {
  throw Error(key.empty() ? std::string(what) : join({key, ": ", what}));
}

[[noreturn]] void expected(const std::string& key, std::string_view what, const json& value) {
  fail(key, join({"expected ", what, ", got ", describe(value)}));
}

void checkObject(const json& value, const std::string& key, std::initializer_list<std::string_view> known) {
  const std::vector<std::string> unknown = unknownKeys(value, key, known);
  if (!unknown.empty()) fail(unknown.front(), join({"unknown key; expected one of ", quotedList(known)}));
}

std::vector<std::string> unknownKeys(const json& value, const std::string& key,
                                     std::initializer_list<std::string_view> known) {
  if (!value.is_object()) expected(key, "an object", value);
  std::vector<std::string> unknown;
  for (const auto& [name, unused] : value.items()) {
    if (std::find(known.begin(), known.end(), name) == known.end()) unknown.push_back(member(key, name));
  }
  return unknown;
}

const json* field(const json& object, std::string_view name) {
  const auto it = object.find(name);
  return it == object.end() ? nullptr : &*it;
}

const json& required(const json& object, const std::string& key, std::string_view name) {
  const json* value = field(object, name);
  if (!value) fail(key, join({"needs \"", name, "\""}));
  return *value;
}

std::int64_t wholeNumber(const json& value, const std::string& key, std::int64_t lo, std::int64_t hi) {
  const std::optional<std::int64_t> n = asWhole(value);
  if (n && *n >= lo && *n <= hi) return *n;
  const std::string range = hi == kMaxInt64
                                ? join({" >= ", std::to_string(lo)})
                                : join({" from ", std::to_string(lo), " to ", std::to_string(hi)});
  expected(key, join({"a whole number", range}), value);
}

std::uint64_t seedNumber(const json& value, const std::string& key) {
  if (value.is_number_unsigned()) return value.get<std::uint64_t>();
  const double d = value.is_number_float() ? value.get<double>() : -1.0;
  if (std::trunc(d) == d && d >= 0.0 && d < 0x1p64) return static_cast<std::uint64_t>(d);
  expected(key, "a whole number from 0 to 18446744073709551615", value);
}

double finiteNumber(const json& value, const std::string& key) {
  if (!value.is_number()) expected(key, "a number", value);
  const double d = value.get<double>();
  if (!std::isfinite(d)) expected(key, "a finite number", value);
  return d;
}

float numberIn(const json& value, const std::string& key, double lo, double hi, bool open) {
  const double d = finiteNumber(value, key);
  const bool inside = open ? d > lo && d < hi : d >= lo && d <= hi;
  if (inside) return static_cast<float>(d);
  const std::string range =
      open ? join({"greater than ", formatNumber(lo), " and less than ", formatNumber(hi)})
           : join({"from ", formatNumber(lo), " to ", formatNumber(hi)});
  expected(key, join({"a number ", range}), value);
}

std::string nonEmptyString(const json& value, const std::string& key) {
  if (!value.is_string() || value.get_ref<const std::string&>().empty())
    expected(key, "a non-empty string", value);
  return value.get<std::string>();
}

std::string oneOf(const json& value, const std::string& key, std::span<const std::string_view> names) {
  const bool known =
      value.is_string() && std::find(names.begin(), names.end(), value.get<std::string>()) != names.end();
  if (!known) expected(key, join({"one of ", quotedList(names)}), value);
  return value.get<std::string>();
}

glm::dvec3 vec3(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != 3) expected(key, "an array of 3 numbers", value);
  glm::dvec3 v;
  for (glm::length_t i = 0; i < 3; ++i) {
    v[i] = finiteNumber(value[static_cast<std::size_t>(i)], element(key, static_cast<std::size_t>(i)));
  }
  return v;
}

bool boolean(const json& value, const std::string& key) {
  if (!value.is_boolean()) expected(key, "true or false", value);
  return value.get<bool>();
}

std::string withFile(const path& file, std::string_view what) {
  return file.empty() ? std::string(what) : locate(file, 0, what);
}

json parseJson(std::string_view text, const path& file) {
  try {
    return json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw Error(join({syntaxPlace(file, text, e.byte), ": invalid JSON: ", jsonDetail(e)}));
  } catch (const json::exception& e) {  // e.g. number overflow in 1e999, which has no position
    throw Error(withFile(file, join({"invalid JSON: ", jsonDetail(e)})));
  }
}

void applyOverride(json& root, const std::string& setting) {
  const std::size_t equals = setting.find('=');
  const std::string name = join({"--set ", setting});
  if (equals == std::string::npos || equals == 0) throw Error(join({name, ": expected key.path=value"}));
  json value = json::parse(setting.substr(equals + 1), nullptr, false);
  if (value.is_discarded()) value = setting.substr(equals + 1);  // a bare word is a string
  json* at = &root;
  std::string_view rest(setting.data(), equals);
  while (true) {
    const std::size_t dot = rest.find('.');
    const std::string part(rest.substr(0, dot));
    if (part.empty()) throw Error(join({name, ": empty key in the path"}));
    const bool index = std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (index && at->is_array()) {
      const std::size_t i = std::stoul(part);
      if (i >= at->size()) throw Error(join({name, ": index ", part, " is past the end of the array"}));
      at = &(*at)[i];
    } else {
      if (!at->is_object()) {
        if (!at->is_null())
          throw Error(join({name, ": \"", part, "\" is inside a value that is not an object"}));
        *at = json::object();
      }
      at = &(*at)[part];
    }
    if (dot == std::string_view::npos) break;
    rest.remove_prefix(dot + 1);
  }
  *at = std::move(value);
}

}  // namespace terrasol::json_check
