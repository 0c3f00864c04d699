#include "controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

#include "core/enum_names.h"

namespace terrasol {
namespace {

constexpr EnumNames<Action, kActionCount> kActionNames{
    {"forward",   "back",     "left",       "right",      "jump",          "sneak",      "sprint",
     "hotbar_1",  "hotbar_2", "hotbar_3",   "hotbar_4",   "hotbar_5",      "hotbar_6",   "hotbar_7",
     "hotbar_8",  "hotbar_9", "hide_hud",   "screenshot", "debug_overlay", "debug_view", "time_faster",
     "time_stop", "time_set", "place_prop", "inventory"}};
constexpr EnumNames<MouseButton, 3> kMouseButtons{{"left", "right", "middle"}};

struct NamedKey {
  std::string_view name;
  int key;
};

constexpr NamedKey kNamedKeys[] = {
    {"SPACE", GLFW_KEY_SPACE},
    {"LEFT_SHIFT", GLFW_KEY_LEFT_SHIFT},
    {"RIGHT_SHIFT", GLFW_KEY_RIGHT_SHIFT},
    {"LEFT_CONTROL", GLFW_KEY_LEFT_CONTROL},
    {"RIGHT_CONTROL", GLFW_KEY_RIGHT_CONTROL},
    {"LEFT_ALT", GLFW_KEY_LEFT_ALT},
    {"RIGHT_ALT", GLFW_KEY_RIGHT_ALT},
    {"TAB", GLFW_KEY_TAB},
    {"ENTER", GLFW_KEY_ENTER},
    {"BACKSPACE", GLFW_KEY_BACKSPACE},
    {"ESCAPE", GLFW_KEY_ESCAPE},
    {"UP", GLFW_KEY_UP},
    {"DOWN", GLFW_KEY_DOWN},
    {"LEFT", GLFW_KEY_LEFT},
    {"RIGHT", GLFW_KEY_RIGHT},
    {"COMMA", GLFW_KEY_COMMA},
    {"PERIOD", GLFW_KEY_PERIOD},
    {"MINUS", GLFW_KEY_MINUS},
    {"EQUAL", GLFW_KEY_EQUAL},
    {"LEFT_BRACKET", GLFW_KEY_LEFT_BRACKET},
    {"RIGHT_BRACKET", GLFW_KEY_RIGHT_BRACKET},
    {"SEMICOLON", GLFW_KEY_SEMICOLON},
    {"SLASH", GLFW_KEY_SLASH},
    {"GRAVE_ACCENT", GLFW_KEY_GRAVE_ACCENT},
};

}  // namespace

std::string_view actionName(Action action) {
  return kActionNames.nameOf(action);
}

std::optional<Action> actionNamed(std::string_view name) {
  return kActionNames.find(name);
}

std::optional<MouseButton> mouseButtonNamed(std::string_view name) {
  return kMouseButtons.find(name);
}

std::optional<int> keyNamed(std::string_view name) {
  if (name.size() == 1 && ((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= '0' && name[0] <= '9'))) {
    return name[0];  // GLFW's codes for letters and digits are their ASCII upper-case codes
  }
  if (name.size() >= 2 && name[0] == 'F') {
    const std::string_view digits = name.substr(1);
    if (std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
        digits.size() <= 2) {
      const int n = std::stoi(std::string(digits));
      if (n >= 1 && n <= 25) return GLFW_KEY_F1 + n - 1;
    }
  }
  for (const NamedKey& k : kNamedKeys)
    if (k.name == name) return k.key;
  return std::nullopt;
}

std::string keyName(int key) {
  if ((key >= 'A' && key <= 'Z') || (key >= '0' && key <= '9')) return std::string(1, static_cast<char>(key));
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25) {
    std::string name = "F";
    name += std::to_string(key - GLFW_KEY_F1 + 1);
    return name;
  }
  for (const NamedKey& k : kNamedKeys)
    if (k.key == key) return std::string(k.name);
  return "UNKNOWN";
}

KeyBindings::KeyBindings() {
  const std::pair<Action, int> defaults[] = {
      {Action::Forward, GLFW_KEY_W},
      {Action::Back, GLFW_KEY_S},
      {Action::Left, GLFW_KEY_A},
      {Action::Right, GLFW_KEY_D},
      {Action::Jump, GLFW_KEY_SPACE},
      {Action::Sneak, GLFW_KEY_LEFT_SHIFT},
      {Action::Sprint, GLFW_KEY_LEFT_CONTROL},
      {Action::HideHud, GLFW_KEY_F1},
      {Action::Screenshot, GLFW_KEY_F2},
      {Action::DebugOverlay, GLFW_KEY_F3},
      {Action::DebugView, GLFW_KEY_F4},
      {Action::TimeFaster, GLFW_KEY_F6},
      {Action::TimeStop, GLFW_KEY_F7},
      {Action::TimeSet, GLFW_KEY_F8},
      {Action::PlaceProp, GLFW_KEY_P},
      {Action::Inventory, GLFW_KEY_E},
  };
  for (const auto& [action, key] : defaults) bind(action, key);
  for (int i = 0; i < 9; ++i)
    bind(static_cast<Action>(static_cast<int>(Action::Hotbar1) + i), GLFW_KEY_1 + i);
}

void Controls::key(int key, bool down) {
  if (key == kEscapeKey) {
    frame_.menuPressed |= down;
    return;
  }
  bindings_->forEachBoundTo(key, [&](Action a) {
    const auto i = static_cast<std::size_t>(a);
    if (down && !frame_.held[i]) frame_.pressed[i] = true;
    frame_.held[i] = down;
  });
}

void Controls::button(MouseButton b, bool down) {
  const auto i = static_cast<std::size_t>(b);
  if (down && !frame_.buttonHeld[i]) frame_.buttonPressed[i] = true;
  frame_.buttonHeld[i] = down;
}

void Controls::releaseAll() {
  frame_.held.reset();
  frame_.buttonHeld = {};
}

FrameInput Controls::take() {
  FrameInput out = frame_;
  frame_.pressed.reset();
  frame_.buttonPressed = {};
  frame_.mouseDelta = glm::dvec2(0.0);
  frame_.scroll = 0.0;
  frame_.menuPressed = false;
  return out;
}

bool DoubleTap::press(double now) {
  if (last_ >= 0.0 && now - last_ <= kSeconds) {
    last_ = -1.0;
    return true;
  }
  last_ = now;
  return false;
}

}  // namespace terrasol
