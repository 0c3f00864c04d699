#include "input_script.h"

#include <algorithm>

#include "core/error.h"
#include "core/json_check.h"
#include "core/paths.h"

namespace terrasol {
namespace {

using namespace json_check;

glm::dvec2 pair(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != 2) expected(key, "an array of 2 numbers", value);
  return {finiteNumber(value[0], element(key, 0)), finiteNumber(value[1], element(key, 1))};
}

ScriptEvent parseEvent(const json& value, const std::string& key) {
  checkObject(value, key, {"t", "key", "button", "down", "look", "mouse_move", "scroll", "command", "model"});
  ScriptEvent e;
  const json* t = field(value, "t");
  if (!t) fail(key, "missing \"t\" (seconds)");
  e.t = numberIn(*t, member(key, "t"), 0.0, 1e6, false);
  int kinds = 0;
  if (const json* v = field(value, "key")) {
    e.kind = ScriptEvent::Kind::Key;
    const std::string name = nonEmptyString(*v, member(key, "key"));
    const auto code = keyNamed(name);
    if (!code)
      fail(member(key, "key"),
           join({"unknown key \"", name, "\" (GLFW names: W, SPACE, LEFT_SHIFT, F3, 1)"}));
    e.key = *code;
    ++kinds;
  }
  if (const json* v = field(value, "button")) {
    e.kind = ScriptEvent::Kind::Button;
    const std::string name = nonEmptyString(*v, member(key, "button"));
    const auto b = mouseButtonNamed(name);
    if (!b)
      fail(member(key, "button"),
           join({"unknown button \"", name, "\"; expected \"left\", \"right\" or \"middle\""}));
    e.button = *b;
    ++kinds;
  }
  if (const json* v = field(value, "look")) {
    e.kind = ScriptEvent::Kind::Look;
    e.value = pair(*v, member(key, "look"));
    if (std::abs(e.value.y) > 90.0) fail(member(key, "look[1]"), "pitch must be within -90..90 degrees");
    ++kinds;
  }
  if (const json* v = field(value, "mouse_move")) {
    e.kind = ScriptEvent::Kind::MouseMove;
    e.value = pair(*v, member(key, "mouse_move"));
    ++kinds;
  }
  if (const json* v = field(value, "scroll")) {
    e.kind = ScriptEvent::Kind::Scroll;
    e.value.x = numberIn(*v, member(key, "scroll"), -100.0, 100.0, false);
    ++kinds;
  }
  if (const json* v = field(value, "command")) {
    e.kind = ScriptEvent::Kind::Command;
    e.command = enumOf<ScriptCommand>(*v, member(key, "command"), kScriptCommands);
    ++kinds;
  }
  const bool placeProp = e.kind == ScriptEvent::Kind::Command && e.command == ScriptCommand::PlaceProp;
  if (const json* v = field(value, "model")) {
    if (!placeProp) fail(member(key, "model"), "only \"place_prop\" takes a model");
    e.model = nonEmptyString(*v, member(key, "model"));
  } else if (placeProp) {
    fail(key, "\"place_prop\" needs \"model\" (a .gltf or .glb file)");
  }
  if (kinds != 1)
    fail(key,
         "expected exactly one of \"key\", \"button\", \"look\", \"mouse_move\", \"scroll\", \"command\"");
  if (const json* v = field(value, "down")) {
    if (e.kind != ScriptEvent::Kind::Key && e.kind != ScriptEvent::Kind::Button) {
      fail(member(key, "down"), "only keys and buttons go down and up");
    }
    e.down = boolean(*v, member(key, "down"));
  }
  return e;
}

InputScript parseRoot(const json& root) {
  checkObject(root, "", {"step", "events"});
  InputScript script;
  if (const json* v = field(root, "step")) script.step = numberIn(*v, "step", 0.001, 1.0, false);
  const json* events = field(root, "events");
  if (!events) fail("events", "missing");
  if (!events->is_array()) expected("events", "an array", *events);
  for (std::size_t i = 0; i < events->size(); ++i)
    script.events.push_back(parseEvent((*events)[i], element("events", i)));
  std::stable_sort(script.events.begin(), script.events.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.t < b.t; });
  return script;
}

}  // namespace

InputScript parseInputScript(std::string_view text, const std::filesystem::path& file) {
  const json root = parseJson(text, file);
  try {
    return parseRoot(root);
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

InputScript loadInputScript(const std::filesystem::path& file) {
  return parseInputScript(readTextFile(file), file);
}

std::vector<ScriptEvent> ScriptPlayer::due(double now) {
  std::vector<ScriptEvent> out;
  while (next_ < script_.events.size() && script_.events[next_].t <= now + 1e-9)
    out.push_back(script_.events[next_++]);
  return out;
}

}  // namespace terrasol
