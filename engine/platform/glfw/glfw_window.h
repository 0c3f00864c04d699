#pragma once
// A GLFW window with an OpenGL 4.5 core context: the game's GlContext.

#include <memory>
#include <string>

#include "core/error.h"
#include "platform/gl_context.h"

struct GLFWwindow;

namespace terrasol {

// Thrown when no display is available (no X server or Wayland compositor, or glfwInit failed).
class NoDisplayError : public Error {
 public:
  using Error::Error;
};

class GlfwWindow final : public GlContext {
 public:
  // Throws NoDisplayError without a display, Error when the window or a 4.5 context cannot be made.
  GlfwWindow(const std::string& title, glm::ivec2 size, GlErrorPolicy policy = GlErrorPolicy::Log);
  ~GlfwWindow() override;

  glm::ivec2 framebufferSize() const override;
  void swapBuffers() override;

  void pollEvents();
  bool shouldClose() const;
  double time() const;  // seconds since the window opened
  void setVsync(bool on);
  // Minimised (iconified): X11 keeps the framebuffer's size then, Windows reports 0x0; the game
  // treats both as a window with no pixels.
  bool minimised() const;
  void minimise();
  void restore();
  GLFWwindow* handle() const { return window_; }  // for input callbacks and the HUD

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace terrasol
