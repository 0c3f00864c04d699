#pragma once
// --input-script FILE: timed key and mouse events replayed through the game's Controls, so tests can
// walk, break, place and save with no person at the keyboard. The game runs a fixed time step while a
// script plays, so a script does the same thing on every machine.
//
//   { "step": 0.05,                       seconds per frame (default 1/60)
//     "events": [
//       { "t": 0.0, "look": [0, 90] },      yaw and pitch in degrees, set at once
//       { "t": 0.1, "key": "W", "down": true },
//       { "t": 0.9, "key": "W", "down": false },
//       { "t": 1.0, "key": "2" },           no "down": pressed for one frame
//       { "t": 1.2, "button": "right" },    "left" | "right" | "middle", same rules
//       { "t": 1.3, "mouse_move": [40, 0] }, pixels, scaled by the mouse sensitivity
//       { "t": 1.4, "scroll": -1 },
//       { "t": 1.8, "command": "place_prop", "model": "box.glb" },  at the targeted face
//       { "t": 2.0, "command": "save" } ] } "save" | "screenshot" | "quit" | "minimise" | "restore"
// Events play in time order once the game clock reaches their "t".

#include <filesystem>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "controls.h"
#include "core/enum_names.h"

namespace terrasol {

enum class ScriptCommand { Save, Screenshot, Quit, Minimise, Restore, PlaceProp };
// Their names in scripts, in ScriptCommand's order.
inline constexpr EnumNames<ScriptCommand, 6> kScriptCommands{
    {"save", "screenshot", "quit", "minimise", "restore", "place_prop"}};
static_assert(kScriptCommands.size() == static_cast<std::size_t>(ScriptCommand::PlaceProp) + 1);

struct ScriptEvent {
  enum class Kind { Key, Button, Look, MouseMove, Scroll, Command } kind = Kind::Key;
  double t = 0.0;
  int key = 0;               // Key
  MouseButton button{};      // Button
  std::optional<bool> down;  // Key, Button: nullopt taps (down this frame, up the next)
  glm::dvec2 value{0.0};     // Look: yaw, pitch; MouseMove: dx, dy; Scroll: x = notches
  ScriptCommand command{};   // Command
  std::string model;         // Command PlaceProp: the glTF file
};

struct InputScript {
  double step = 1.0 / 60.0;
  std::vector<ScriptEvent> events;  // sorted by t (stable: equal times keep file order)
};

// Throws Error naming the file, the event ("events[3].key") and what is wrong.
InputScript parseInputScript(std::string_view json, const std::filesystem::path& file);
InputScript loadInputScript(const std::filesystem::path& file);

// Hands out a script's events as the game clock passes them.
class ScriptPlayer {
 public:
  explicit ScriptPlayer(InputScript script) : script_(std::move(script)) {}
  double step() const { return script_.step; }
  // Events with t <= `now` not handed out yet.
  std::vector<ScriptEvent> due(double now);
  bool finished() const { return next_ >= script_.events.size(); }

 private:
  InputScript script_;
  std::size_t next_ = 0;
};

}  // namespace terrasol
