#include "settings.h"

#include <cstdlib>

#include "core/error.h"
#include "core/json_check.h"
#include "core/render_scale.h"

namespace terrasol {
namespace {

using namespace json_check;

std::vector<PackChoice> parsePacks(const json& value, const path& dir) {
  if (!value.is_array()) expected("packs", "an array", value);
  std::vector<PackChoice> packs;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string key = element("packs", i);
    checkObject(value[i], key, {"path", "enabled"});
    const json* p = field(value[i], "path");
    if (!p) fail(key, "missing \"path\"");
    PackChoice pack;
    pack.path = nonEmptyString(*p, member(key, "path"));
    if (pack.path.is_relative()) pack.path = dir / pack.path;
    if (const json* e = field(value[i], "enabled")) pack.enabled = boolean(*e, member(key, "enabled"));
    packs.push_back(std::move(pack));
  }
  return packs;
}

void parseSound(const json& value, AudioVolumes& v) {
  checkObject(value, "sound", {"master", "blocks", "ambient", "music"});
  for (auto [name, target] : {std::pair{"master", &v.master}, std::pair{"blocks", &v.blocks},
                              std::pair{"ambient", &v.ambient}, std::pair{"music", &v.music}}) {
    if (const json* f = field(value, name)) *target = numberIn(*f, member("sound", name), 0.0, 1.0, false);
  }
}

void parseKeys(const json& value, KeyBindings& keys) {
  if (!value.is_object()) expected("keys", "an object", value);
  for (const auto& [name, k] : value.items()) {
    const std::string key = member("keys", name);
    const auto action = actionNamed(name);
    if (!action) fail(key, "unknown action");
    const std::string keyText = nonEmptyString(k, key);
    const auto code = keyNamed(keyText);
    if (!code) fail(key, join({"unknown key \"", keyText, "\""}));
    if (*code == kEscapeKey) fail(key, "ESCAPE always opens the menu");
    keys.bind(*action, *code);
  }
}

GameSettings parseRoot(const json& root, const path& dir) {
  checkObject(root, "",
              {"view_distance",
               "fov",
               "mouse_sensitivity",
               "sun_path_rotation",
               "survival_digging",
               "shadow",
               "reflections",
               "antialiasing",
               "bloom",
               "clouds",
               "fog",
               "shafts",
               "lod",
               "packs",
               "shaderpack",
               "keys",
               "sound",
               "vsync",
               "render_scale",
               "target_fps",
               "first_run"});
  GameSettings s;
  if (const json* v = field(root, "view_distance"))
    s.viewDistance = static_cast<int>(wholeNumber(*v, "view_distance", 2, 32));
  if (const json* v = field(root, "fov")) s.fov = numberIn(*v, "fov", 30.0, 110.0, false);
  if (const json* v = field(root, "mouse_sensitivity"))
    s.mouseSensitivity = numberIn(*v, "mouse_sensitivity", 0.01, 2.0, false);
  if (const json* v = field(root, "sun_path_rotation"))
    s.sunPathRotation = numberIn(*v, "sun_path_rotation", -90.0, 90.0, false);
  if (const json* v = field(root, "survival_digging")) s.survivalDigging = boolean(*v, "survival_digging");
  if (const json* v = field(root, "shadow")) parseShadow(*v, "shadow", s.shadow);
  if (const json* v = field(root, "reflections")) parseReflections(*v, "reflections", s.reflections);
  if (const json* v = field(root, "bloom")) parseBloom(*v, "bloom", s.bloom);
  if (const json* v = field(root, "clouds")) parseClouds(*v, "clouds", s.clouds);
  if (const json* v = field(root, "fog")) parseFog(*v, "fog", s.fog);
  if (const json* v = field(root, "shafts")) parseShafts(*v, "shafts", s.shafts);
  if (const json* v = field(root, "lod")) parseLod(*v, "lod", s.lod);
  if (const json* v = field(root, "antialiasing"))
    s.antialiasing = enumOf(*v, "antialiasing", kAntialiasingModes);
  if (const json* v = field(root, "packs")) s.packs = parsePacks(*v, dir);
  // "": Terrasol's own pipeline.
  if (const json* v = field(root, "shaderpack"); v && !(v->is_string() && v->get<std::string>().empty()))
    s.shaderpack = dir / nonEmptyString(*v, "shaderpack");
  if (const json* v = field(root, "keys")) parseKeys(*v, s.keys);
  if (const json* v = field(root, "sound")) parseSound(*v, s.sound);
  if (const json* v = field(root, "vsync")) s.vsync = boolean(*v, "vsync");
  if (const json* v = field(root, "render_scale"))
    s.renderScale = numberIn(*v, "render_scale", kMinRenderScale, kMaxRenderScale, false);
  if (const json* v = field(root, "target_fps"))
    s.targetFps = static_cast<int>(wholeNumber(*v, "target_fps", 0, 1000));
  if (const json* v = field(root, "first_run")) {
    checkObject(*v, "first_run", {"gl", "frame_ms", "choice"});
    FirstRunRecord r;
    if (const json* g = field(*v, "gl")) r.glRenderer = nonEmptyString(*g, "first_run.gl");
    if (const json* m = field(*v, "frame_ms"))
      r.frameMs = numberIn(*m, "first_run.frame_ms", 0.0, 1e6, false);
    if (const json* c = field(*v, "choice")) r.choice = nonEmptyString(*c, "first_run.choice");
    s.firstRun = r;
  }
  return s;
}

}  // namespace

GameSettings parseSettings(std::string_view text, const std::filesystem::path& file) {
  const json root = parseJson(text, file);
  try {
    return parseRoot(root, file.parent_path());
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

GameSettings loadSettings(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return {};
  return parseSettings(readTextFile(file), file);
}

void saveSettings(const std::filesystem::path& file, const GameSettings& s) {
  json packs = json::array();
  for (const PackChoice& p : s.packs) packs.push_back({{"path", p.path.string()}, {"enabled", p.enabled}});
  json keys = json::object();
  for (std::size_t i = 0; i < kActionCount; ++i) {
    const auto a = static_cast<Action>(i);
    keys[std::string(actionName(a))] = keyName(s.keys.key(a));
  }
  json root = {{"view_distance", s.viewDistance},
               {"fov", s.fov},
               {"mouse_sensitivity", s.mouseSensitivity},
               {"sun_path_rotation", s.sunPathRotation},
               {"survival_digging", s.survivalDigging},
               {"shadow", shadowJson(s.shadow)},
               {"reflections", reflectionsJson(s.reflections)},
               {"antialiasing", std::string(kAntialiasingModes.nameOf(s.antialiasing))},
               {"bloom", bloomJson(s.bloom)},
               {"clouds", cloudsJson(s.clouds)},
               {"fog", fogJson(s.fog)},
               {"shafts", shaftsJson(s.shafts)},
               {"lod", lodJson(s.lod)},
               {"packs", packs},
               {"shaderpack", s.shaderpack.string()},
               {"keys", keys},
               {"sound",
                {{"master", s.sound.master},
                 {"blocks", s.sound.blocks},
                 {"ambient", s.sound.ambient},
                 {"music", s.sound.music}}},
               {"vsync", s.vsync},
               {"render_scale", s.renderScale},
               {"target_fps", s.targetFps}};
  if (s.firstRun) {
    root["first_run"] = {
        {"gl", s.firstRun->glRenderer}, {"frame_ms", s.firstRun->frameMs}, {"choice", s.firstRun->choice}};
  }
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  writeFileAtomically(file, root.dump(2) + "\n");
}

std::filesystem::path defaultSettingsFile() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "terrasol" / "settings.json";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".config" / "terrasol" / "settings.json";
  return "terrasol-settings.json";
}

}  // namespace terrasol
