#pragma once
// Checked reading of JSON documents (scene files, settings, input scripts, block models, blocks.json,
// level.json, pack metadata): every error names the key path ("render.shadow.resolution",
// "events[3].key") and what was expected, and the caller adds the file. Throws Error.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/enum_names.h"

namespace terrasol::json_check {

using nlohmann::json;
using std::filesystem::path;

// Appends, never `"literal" + std::string` chains (gcc 12 warns wrongly about those under -Werror).
std::string join(std::initializer_list<std::string_view> parts);
// Key paths: member("render", "width") is "render.width"; element("packs", 0) is "packs[0]".
std::string member(const std::string& parent, std::string_view name);
std::string element(const std::string& parent, std::size_t index);

// `key` is the full key path; empty for the top level.
[[noreturn]] void fail(const std::string& key, std::string_view what);
[[noreturn]] void expected(const std::string& key, std::string_view what, const json& value);

// Checks that `value` is an object and that every key in it is one of `known` (catches typos).
void checkObject(const json& value, const std::string& key, std::initializer_list<std::string_view> known);
// The key paths of the members of object `value` that are not in `known`: for files whose other keys
// belong to someone else (Minecraft's pack.mcmeta), where the caller warns instead of failing.
std::vector<std::string> unknownKeys(const json& value, const std::string& key,
                                     std::initializer_list<std::string_view> known);
// The member `name` of an object already checked, or null when absent.
const json* field(const json& object, std::string_view name);
// The same, failing with `needs "name"` when absent.
const json& required(const json& object, const std::string& key, std::string_view name);

// Integers, and floats with no fraction (1e9 is a float to nlohmann), within [lo, hi].
std::int64_t wholeNumber(const json& value, const std::string& key, std::int64_t lo, std::int64_t hi);
std::uint64_t seedNumber(const json& value, const std::string& key);
double finiteNumber(const json& value, const std::string& key);
// Within [lo, hi], or (lo, hi) when `open`.
float numberIn(const json& value, const std::string& key, double lo, double hi, bool open);
std::string nonEmptyString(const json& value, const std::string& key);
std::string oneOf(const json& value, const std::string& key, std::span<const std::string_view> names);
// The enum value the string names in `names`.
template <class E, std::size_t N>
E enumOf(const json& value, const std::string& key, const EnumNames<E, N>& names) {
  const std::optional<E> e = value.is_string() ? names.find(value.get<std::string>()) : std::nullopt;
  if (!e) expected(key, join({"one of ", names.list()}), value);
  return *e;
}
glm::dvec3 vec3(const json& value, const std::string& key);
bool boolean(const json& value, const std::string& key);

// "FILE: what" (just `what` for an unnamed document).
std::string withFile(const path& file, std::string_view what);
// Parses with comments allowed; syntax errors name FILE:LINE:COLUMN.
json parseJson(std::string_view text, const path& file);
// One "--set key.path=value" applied to the parsed document (a bare word is a string).
void applyOverride(json& root, const std::string& setting);

}  // namespace terrasol::json_check
