#include "script_driver.h"

namespace terrasol {

std::vector<ScriptEvent> ScriptDriver::play(double dt, InputRouter& input, Player& player) {
  Controls& controls = input.controls();
  for (int key : keyTaps_) controls.key(key, false);
  for (MouseButton b : buttonTaps_) controls.button(b, false);
  keyTaps_.clear();
  buttonTaps_.clear();
  std::vector<ScriptEvent> commands;
  for (const ScriptEvent& e : player_.due(clock_)) {
    switch (e.kind) {
      case ScriptEvent::Kind::Key:
        if (input.screenOpen() && e.key != kEscapeKey) break;  // as the window's keys
        controls.key(e.key, e.down.value_or(true));
        if (!e.down) keyTaps_.push_back(e.key);
        break;
      case ScriptEvent::Kind::Button:
        controls.button(e.button, e.down.value_or(true));
        if (!e.down) buttonTaps_.push_back(e.button);
        break;
      case ScriptEvent::Kind::Look:
        player.yaw = static_cast<float>(e.value.x);
        player.pitch = static_cast<float>(e.value.y);
        break;
      case ScriptEvent::Kind::MouseMove:
        controls.mouseMoved(e.value);
        break;
      case ScriptEvent::Kind::Scroll:
        controls.scrolled(e.value.x);
        break;
      case ScriptEvent::Kind::Command:
        commands.push_back(e);
        break;
    }
  }
  clock_ += dt;
  return commands;
}

}  // namespace terrasol
