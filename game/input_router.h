#pragma once
// Where the window's input goes: the one receiver of GLFW's callbacks. With no screen open, keys,
// buttons, motion and the wheel go to the game's Controls; while the menu or the inventory is open
// the cursor is free and they go to that screen (ImGui, which chains to these callbacks), but Esc.

#include "controls.h"

struct GLFWwindow;

namespace terrasol {

class GlfwWindow;

enum class Screen { None, Menu, Inventory };

// What an open screen does with a key before anything else.
class ScreenKeys {
 public:
  virtual bool takeKey(int key) = 0;  // true when taken (the menu waiting for a key to bind)
  virtual bool typing() const = 0;    // a text field has the keyboard: letters are typing
 protected:
  ~ScreenKeys() = default;
};

class InputRouter {
 public:
  // Installs the window's callbacks; install ImGui's after, so that they chain to these.
  InputRouter(GlfwWindow& window, const KeyBindings& keys);
  InputRouter(const InputRouter&) = delete;  // the window holds its address
  InputRouter& operator=(const InputRouter&) = delete;

  void setScreenKeys(ScreenKeys* keys) { screenKeys_ = keys; }
  Controls& controls() { return controls_; }
  Screen screen() const { return screen_; }
  bool screenOpen() const { return screen_ != Screen::None; }
  // Opens a screen (or closes them with None): everything held is let go, and the cursor is free
  // while a screen is open, captured for looking round otherwise.
  void show(Screen screen);
  FrameInput take() { return controls_.take(); }

 private:
  static InputRouter& of(GLFWwindow* window);
  void key(int key, int action);
  void button(int button, int action);
  void cursor(double x, double y);

  GlfwWindow& window_;
  const KeyBindings& keys_;
  Controls controls_;
  ScreenKeys* screenKeys_ = nullptr;
  Screen screen_ = Screen::None;
  glm::dvec2 lastCursor_{0.0};
  bool cursorKnown_ = false;  // motion counts from the second position after a change
};

}  // namespace terrasol
