#pragma once
// Minecraft's controls as actions bound to keys, and the input of one frame: what is held, what was
// pressed since the last frame, mouse motion and wheel. Window callbacks and input scripts feed the
// same Controls, so a script plays exactly what a person would. Plain C++ (GLFW key codes as ints).

#include <array>
#include <bitset>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace terrasol {

enum class Action {
  Forward,
  Back,
  Left,
  Right,
  Jump,
  Sneak,
  Sprint,
  Hotbar1,
  Hotbar2,
  Hotbar3,
  Hotbar4,
  Hotbar5,
  Hotbar6,
  Hotbar7,
  Hotbar8,
  Hotbar9,
  HideHud,
  Screenshot,
  DebugOverlay,
  DebugView,
  TimeFaster,
  TimeStop,
  TimeSet,
  PlaceProp,
  Inventory,
  Count
};
inline constexpr std::size_t kActionCount = static_cast<std::size_t>(Action::Count);

// Settings-file names ("forward", "hotbar_1", ...), in Action order.
std::string_view actionName(Action action);
std::optional<Action> actionNamed(std::string_view name);

enum class MouseButton { Left, Right, Middle, Count };
std::optional<MouseButton> mouseButtonNamed(std::string_view name);

// Key names as GLFW spells them without the prefix ("W", "SPACE", "LEFT_SHIFT", "F3", "1");
// nullopt / "UNKNOWN" for codes and names outside the table.
std::optional<int> keyNamed(std::string_view name);
std::string keyName(int key);
inline constexpr int kEscapeKey = 256;  // GLFW_KEY_ESCAPE: opens the menu, never rebound

class KeyBindings {
 public:
  KeyBindings();  // Minecraft's defaults, plus F4 debug view, F6/F7/F8 time
  int key(Action a) const { return keys_[static_cast<std::size_t>(a)]; }
  void bind(Action a, int key) { keys_[static_cast<std::size_t>(a)] = key; }
  // Every action bound to `key` (a key may serve several, as in Minecraft).
  template <class F>
  void forEachBoundTo(int key, F&& f) const {
    for (std::size_t i = 0; i < kActionCount; ++i)
      if (keys_[i] == key) f(static_cast<Action>(i));
  }

 private:
  std::array<int, kActionCount> keys_{};
};

// One frame's input.
struct FrameInput {
  std::bitset<kActionCount> held, pressed;
  std::array<bool, static_cast<std::size_t>(MouseButton::Count)> buttonHeld{}, buttonPressed{};
  glm::dvec2 mouseDelta{0.0};  // pixels
  double scroll = 0.0;         // wheel notches, + up
  bool menuPressed = false;    // Esc
  bool isHeld(Action a) const { return held[static_cast<std::size_t>(a)]; }
  bool wasPressed(Action a) const { return pressed[static_cast<std::size_t>(a)]; }
  bool isHeld(MouseButton b) const { return buttonHeld[static_cast<std::size_t>(b)]; }
  bool wasPressed(MouseButton b) const { return buttonPressed[static_cast<std::size_t>(b)]; }
};

// Two presses of a key close together, as Minecraft's double-tapped jump that toggles flight.
class DoubleTap {
 public:
  static constexpr double kSeconds = 0.3;
  // A press at `now` (seconds): true when it is the second of two within kSeconds.
  bool press(double now);

 private:
  double last_ = -1.0;  // the first press's time; -1 when none is waiting for its second
};

class Controls {
 public:
  explicit Controls(const KeyBindings& bindings) : bindings_(&bindings) {}

  void key(int key, bool down);
  void button(MouseButton b, bool down);
  void mouseMoved(glm::dvec2 delta) { frame_.mouseDelta += delta; }
  void scrolled(double notches) { frame_.scroll += notches; }
  // Lets go of everything (the menu opened, the window lost focus).
  void releaseAll();

  // This frame's input; the next frame starts with the same keys held and nothing pressed.
  FrameInput take();

 private:
  const KeyBindings* bindings_;
  FrameInput frame_;
};

}  // namespace terrasol
