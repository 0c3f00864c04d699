#include "scene/scene_file.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <sstream>

#include "core/error.h"
#include "core/paths.h"

namespace terrasol {
namespace {

using nlohmann::json;
using std::filesystem::path;

constexpr std::array<std::string_view, 3> kGenerators = {"void", "flat", "terrain"};
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kMinInt32 = std::numeric_limits<std::int32_t>::min();
constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxFrames = 100000;

// Appends, never `"literal" + std::string` chains (gcc 12 warns wrongly about those under -Werror).
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

// `key` is the full key path ("render.width", "packs[0]"); empty for the top level.
[[noreturn]] void fail(const std::string& key, std::string_view what) {
  throw Error(key.empty() ? std::string(what) : join({key, ": ", what}));
}

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

[[noreturn]] void expected(const std::string& key, std::string_view what, const json& value) {
  fail(key, join({"expected ", what, ", got ", describe(value)}));
}

std::string quotedList(std::span<const std::string_view> names) {
  std::string list;
  for (std::string_view name : names) list += join({list.empty() ? "" : ", ", "\"", name, "\""});
  return list;
}

// Checks that `value` is an object and that every key in it is one of `known` (catches typos).
void checkObject(const json& value, const std::string& key, std::initializer_list<std::string_view> known) {
  if (!value.is_object()) expected(key, "an object", value);
  for (const auto& [name, unused] : value.items()) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      fail(member(key, name), join({"unknown key; expected one of ", quotedList(known)}));
    }
  }
}

// The member `name` of an object already checked, or null when absent.
const json* field(const json& object, std::string_view name) {
  const auto it = object.find(name);
  return it == object.end() ? nullptr : &*it;
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

std::string formatNumber(double d) {
  std::ostringstream out;
  out << d;
  return out.str();
}

// Within [lo, hi], or (lo, hi) when `open`.
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

template <std::size_t N>
std::array<int, N> cells(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != N) {
    expected(key, join({"an array of ", std::to_string(N), " whole numbers"}), value);
  }
  std::array<int, N> out{};
  for (std::size_t i = 0; i < N; ++i) {
    out[i] = static_cast<int>(wholeNumber(value[i], element(key, i), kMinInt32, kMaxInt32));
  }
  return out;
}

SceneEdit parseEdit(const json& value, const std::string& key) {
  checkObject(value, key, {"fill", "set", "block", "at_frame"});
  const json* fill = field(value, "fill");
  const json* set = field(value, "set");
  if (fill && set) fail(key, "has both \"fill\" and \"set\"; give one");
  if (!fill && !set) fail(key, "needs \"fill\" (a box) or \"set\" (one block)");
  const json* block = field(value, "block");
  if (!block) fail(key, "needs \"block\"");
  SceneEdit edit;
  edit.key = key;
  edit.block = nonEmptyString(*block, member(key, "block"));
  if (fill) {
    const auto c = cells<6>(*fill, member(key, "fill"));
    edit.kind = SceneEdit::Kind::Fill;
    edit.from = glm::min(glm::ivec3(c[0], c[1], c[2]), glm::ivec3(c[3], c[4], c[5]));
    edit.to = glm::max(glm::ivec3(c[0], c[1], c[2]), glm::ivec3(c[3], c[4], c[5]));
  } else {
    const auto c = cells<3>(*set, member(key, "set"));
    edit.from = edit.to = glm::ivec3(c[0], c[1], c[2]);
  }
  if (const json* f = field(value, "at_frame")) {
    edit.atFrame = static_cast<int>(wholeNumber(*f, member(key, "at_frame"), 0, kMaxFrames - 1));
  }
  return edit;
}

std::vector<SceneEdit> parseEdits(const json& value, const std::string& key) {
  if (!value.is_array()) expected(key, "an array of edits", value);
  std::vector<SceneEdit> edits;
  for (std::size_t i = 0; i < value.size(); ++i) edits.push_back(parseEdit(value[i], element(key, i)));
  return edits;
}

void parseWorld(const json& world, SceneFile& scene) {
  checkObject(world, "world", {"generator", "seed", "edits"});
  if (const json* v = field(world, "generator")) scene.generator = oneOf(*v, "world.generator", kGenerators);
  if (const json* v = field(world, "seed")) scene.seed = seedNumber(*v, "world.seed");
  if (const json* v = field(world, "edits")) scene.edits = parseEdits(*v, "world.edits");
}

path resolvePack(const std::string& name, const path& sceneDir) {
  if (name == "default") return resourcePackDir() / "default";
  const path pack(name);
  return pack.is_absolute() ? pack : (sceneDir / pack).lexically_normal();
}

std::vector<path> parsePacks(const json& value, const path& sceneDir) {
  if (!value.is_array() || value.empty()) expected("packs", "a non-empty array of pack paths", value);
  std::vector<path> packs;
  for (std::size_t i = 0; i < value.size(); ++i) {
    packs.push_back(resolvePack(nonEmptyString(value[i], element("packs", i)), sceneDir));
  }
  return packs;
}


bool boolean(const json& value, const std::string& key) {
  if (!value.is_boolean()) expected(key, "true or false", value);
  return value.get<bool>();
}

void parsePcf(const json& pcf, SceneShadow& shadow) {
  checkObject(pcf, "render.shadow.pcf", {"samples", "radius", "radius_unit", "pattern"});
  if (const json* v = field(pcf, "samples")) {
    shadow.pcfSamples = static_cast<int>(wholeNumber(*v, "render.shadow.pcf.samples", 0, 8));
  }
  if (const json* v = field(pcf, "radius")) shadow.pcfRadius = numberIn(*v, "render.shadow.pcf.radius", 0.0, 32.0, false);
  if (const json* v = field(pcf, "pattern")) shadow.pcfPattern = oneOf(*v, "render.shadow.pcf.pattern", kPcfPatterns);
  if (const json* v = field(pcf, "radius_unit")) {
    shadow.pcfRadiusUnit = oneOf(*v, "render.shadow.pcf.radius_unit", kPcfRadiusUnits);
  }
}

void parseShadow(const json& value, SceneShadow& shadow) {
  const std::string key = "render.shadow";
  checkObject(value, key,
              {"enabled", "mode", "cascades", "resolution", "distance", "warp", "warp_strength", "pcf", "shift_ahead"});
  if (const json* v = field(value, "enabled")) shadow.enabled = boolean(*v, member(key, "enabled"));
  if (const json* v = field(value, "mode")) shadow.mode = oneOf(*v, member(key, "mode"), kShadowModes);
  if (const json* v = field(value, "cascades")) {
    shadow.cascades = static_cast<int>(wholeNumber(*v, member(key, "cascades"), 2, 4));
  }
  if (const json* v = field(value, "resolution")) {
    shadow.resolution = static_cast<int>(wholeNumber(*v, member(key, "resolution"), 16, 16384));
  }
  if (const json* v = field(value, "distance")) shadow.distance = numberIn(*v, member(key, "distance"), 1.0, 4096.0, false);
  if (const json* v = field(value, "warp")) shadow.warp = oneOf(*v, member(key, "warp"), kShadowWarps);
  if (const json* v = field(value, "warp_strength")) {
    const double a = finiteNumber(*v, member(key, "warp_strength"));
    if (a < 0.0 || a >= 1.0) expected(member(key, "warp_strength"), "a number from 0 up to (not including) 1", *v);
    shadow.warpStrength = static_cast<float>(a);
  }
  if (const json* v = field(value, "pcf")) parsePcf(*v, shadow);
  if (const json* v = field(value, "shift_ahead")) shadow.shiftAhead = numberIn(*v, member(key, "shift_ahead"), 0.0, 0.9, false);
}

void parseRender(const json& render, SceneFile& scene) {
  checkObject(render, "render", {"width", "height", "view_distance", "debug_view", "specular", "material_ao", "shadow"});
  if (const json* v = field(render, "width")) {
    scene.width = static_cast<int>(wholeNumber(*v, "render.width", 1, 8192));
  }
  if (const json* v = field(render, "height")) {
    scene.height = static_cast<int>(wholeNumber(*v, "render.height", 1, 8192));
  }
  if (const json* v = field(render, "view_distance")) {
    scene.viewDistance = static_cast<int>(wholeNumber(*v, "render.view_distance", 0, 32));
  }
  if (const json* v = field(render, "debug_view")) {
    scene.debugView = oneOf(*v, "render.debug_view", kDebugViews);
  }
  if (const json* v = field(render, "specular")) scene.specular = oneOf(*v, "render.specular", kSpecularModels);
  if (const json* v = field(render, "material_ao")) scene.materialAo = boolean(*v, "render.material_ao");
  if (const json* v = field(render, "shadow")) parseShadow(*v, scene.shadow);
}

void parseCamera(const json& camera, SceneFile& scene) {
  checkObject(camera, "camera", {"position", "look_at", "fov"});
  if (const json* v = field(camera, "position")) scene.cameraPosition = vec3(*v, "camera.position");
  if (const json* v = field(camera, "look_at")) scene.cameraLookAt = vec3(*v, "camera.look_at");
  if (const json* v = field(camera, "fov")) scene.fov = numberIn(*v, "camera.fov", 0.0, 180.0, true);
}

CameraKeyframe parseKeyframe(const json& value, const std::string& key, const SceneFile& scene) {
  checkObject(value, key, {"t", "position", "look_at", "fov", "time"});
  for (const char* required : {"t", "position", "look_at"}) {
    if (!field(value, required)) fail(key, join({"needs \"", required, "\""}));
  }
  CameraKeyframe k;
  k.t = numberIn(*field(value, "t"), member(key, "t"), 0.0, 1.0, false);
  k.position = vec3(*field(value, "position"), member(key, "position"));
  k.lookAt = vec3(*field(value, "look_at"), member(key, "look_at"));
  k.fov = scene.fov;
  k.time = scene.time;
  if (const json* v = field(value, "fov")) k.fov = numberIn(*v, member(key, "fov"), 0.0, 180.0, true);
  if (const json* v = field(value, "time")) k.time = wholeNumber(*v, member(key, "time"), 0, kMaxInt64);
  return k;
}

// After "camera" and "time", whose values are the keyframes' defaults.
CameraPath parseCameraPath(const json& value, const SceneFile& scene) {
  checkObject(value, "camera_path", {"frames", "keyframes"});
  CameraPath path;
  if (const json* v = field(value, "frames")) {
    path.frames = static_cast<int>(wholeNumber(*v, "camera_path.frames", 1, kMaxFrames));
  }
  const json* keyframes = field(value, "keyframes");
  if (!keyframes) fail("camera_path", "needs \"keyframes\"");
  if (!keyframes->is_array() || keyframes->empty()) {
    expected("camera_path.keyframes", "a non-empty array of keyframes", *keyframes);
  }
  for (std::size_t i = 0; i < keyframes->size(); ++i) {
    const std::string key = element("camera_path.keyframes", i);
    path.keyframes.push_back(parseKeyframe((*keyframes)[i], key, scene));
    if (i > 0 && path.keyframes[i].t <= path.keyframes[i - 1].t) {
      fail(member(key, "t"), "must be greater than the previous keyframe's");
    }
  }
  return path;
}

void parseCompare(const json& value, SceneFile& scene) {
  checkObject(value, "compare", {"pixel_threshold", "max_failing_percent"});
  if (const json* v = field(value, "pixel_threshold")) {
    scene.compare.pixelThreshold = numberIn(*v, "compare.pixel_threshold", 0.0, 1.0, false);
  }
  if (const json* v = field(value, "max_failing_percent")) {
    scene.compare.maxFailingPercent = numberIn(*v, "compare.max_failing_percent", 0.0, 100.0, false);
  }
}

// Edits keyed to frames must name a frame the scene has.
void checkEditFrames(const SceneFile& scene) {
  for (const SceneEdit& edit : scene.edits) {
    if (edit.atFrame >= scene.frameCount()) {
      fail(member(edit.key, "at_frame"),
           join({"the scene has ", std::to_string(scene.frameCount()), " frame(s), numbered from 0"}));
    }
  }
}

SceneFile parseRoot(const json& root, const path& file) {
  checkObject(root, "", {"world", "packs", "time", "sun_path_rotation", "render", "camera", "camera_path", "compare"});
  SceneFile scene;
  scene.file = file;
  if (const json* v = field(root, "world")) parseWorld(*v, scene);
  const json* packs = field(root, "packs");
  scene.packs =
      packs ? parsePacks(*packs, file.parent_path()) : std::vector<path>{resourcePackDir() / "default"};
  if (const json* v = field(root, "time")) scene.time = wholeNumber(*v, "time", 0, kMaxInt64);
  if (const json* v = field(root, "sun_path_rotation")) {
    scene.sunPathRotation = numberIn(*v, "sun_path_rotation", -90.0, 90.0, false);
  }
  if (const json* v = field(root, "render")) parseRender(*v, scene);
  if (const json* v = field(root, "camera")) parseCamera(*v, scene);
  if (const json* v = field(root, "camera_path")) scene.cameraPath = parseCameraPath(*v, scene);
  if (const json* v = field(root, "compare")) parseCompare(*v, scene);
  checkEditFrames(scene);
  return scene;
}

std::string withFile(const path& file, std::string_view what) {
  return file.empty() ? std::string(what) : locate(file, 0, what);
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

json parseJson(std::string_view text, const path& file) {
  try {
    return json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw Error(join({syntaxPlace(file, text, e.byte), ": invalid JSON: ", jsonDetail(e)}));
  } catch (const json::exception& e) {  // e.g. number overflow in 1e999, which has no position
    throw Error(withFile(file, join({"invalid JSON: ", jsonDetail(e)})));
  }
}

// One "--set key.path=value" applied to the parsed document.
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
        if (!at->is_null()) throw Error(join({name, ": \"", part, "\" is inside a value that is not an object"}));
        *at = json::object();
      }
      at = &(*at)[part];
    }
    if (dot == std::string_view::npos) break;
    rest.remove_prefix(dot + 1);
  }
  *at = std::move(value);
}

SceneFile parseChecked(const nlohmann::json& root, const std::filesystem::path& file) {
  try {
    return parseRoot(root, file);
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

}  // namespace

std::string sceneError(const SceneFile& scene, std::string_view key, std::string_view what) {
  return withFile(scene.file, join({key, ": ", what}));
}

SceneFile parseScene(std::string_view json, const std::filesystem::path& file) {
  return parseChecked(parseJson(json, file), file);
}

SceneFile loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  if (std::filesystem::is_directory(file)) throw Error(locate(file, 0, "is a directory, not a scene file"));
  if (overrides.empty()) return parseScene(readTextFile(file), file);
  nlohmann::json root = parseJson(readTextFile(file), file);
  for (const std::string& setting : overrides) applyOverride(root, setting);
  return parseChecked(root, file);
}

}  // namespace terrasol
