#include "input_router.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "platform/glfw/glfw_window.h"

namespace terrasol {

InputRouter::InputRouter(GlfwWindow& window, const KeyBindings& keys)
    : window_(window), keys_(keys), controls_(keys) {
  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) { of(win).key(key, action); });
  glfwSetMouseButtonCallback(
      w, [](GLFWwindow* win, int button, int action, int) { of(win).button(button, action); });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) { of(win).cursor(x, y); });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double y) {
    if (!of(win).screenOpen()) of(win).controls_.scrolled(y);
  });
  glfwSetWindowFocusCallback(w, [](GLFWwindow* win, int focused) {
    if (!focused) of(win).controls_.releaseAll();  // keys let go elsewhere never reach us
  });
}

InputRouter& InputRouter::of(GLFWwindow* window) {
  return *static_cast<InputRouter*>(glfwGetWindowUserPointer(window));
}

void InputRouter::show(Screen screen) {
  screen_ = screen;
  controls_.releaseAll();
  cursorKnown_ = false;
  GLFWwindow* w = window_.handle();
  glfwSetInputMode(w, GLFW_CURSOR, screenOpen() ? GLFW_CURSOR_NORMAL : GLFW_CURSOR_DISABLED);
  if (!screenOpen() && glfwRawMouseMotionSupported()) glfwSetInputMode(w, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
}

void InputRouter::key(int key, int action) {
  if (action == GLFW_REPEAT) return;
  if (screenOpen()) {
    const bool press = action == GLFW_PRESS;
    if (screen_ == Screen::Menu && press && screenKeys_ && screenKeys_->takeKey(key)) return;
    // The inventory's key closes it, unless the search field is being typed in.
    if (screen_ == Screen::Inventory && press && key == keys_.key(Action::Inventory) &&
        !(screenKeys_ && screenKeys_->typing())) {
      show(Screen::None);
      return;
    }
    if (key != kEscapeKey) return;  // the screens' own typing goes to ImGui
  }
  controls_.key(key, action == GLFW_PRESS);
}

void InputRouter::button(int button, int action) {
  if (screenOpen()) return;
  const MouseButton b = button == GLFW_MOUSE_BUTTON_LEFT    ? MouseButton::Left
                        : button == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::Right
                                                            : MouseButton::Middle;
  controls_.button(b, action == GLFW_PRESS);
}

void InputRouter::cursor(double x, double y) {
  if (cursorKnown_ && !screenOpen()) controls_.mouseMoved(glm::dvec2(x, y) - lastCursor_);
  lastCursor_ = {x, y};
  cursorKnown_ = true;
}

}  // namespace terrasol
