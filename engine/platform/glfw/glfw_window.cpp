#include "platform/glfw/glfw_window.h"

#include <epoxy/gl.h>
// epoxy provides the GL declarations; GLFW must not include its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

namespace terrasol {
namespace {

std::string glfwErrorText() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "unknown GLFW error";
}

}  // namespace

GlfwWindow::GlfwWindow(const std::string& title, glm::ivec2 size, GlErrorPolicy policy) : GlContext(policy) {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!x || !*x) && (!wayland || !*wayland)) {
    throw NoDisplayError("no display: neither DISPLAY nor WAYLAND_DISPLAY is set");
  }
  if (!glfwInit()) throw NoDisplayError("cannot open the display: " + glfwErrorText());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = glfwErrorText();
    glfwTerminate();
    throw Error("cannot create a window with OpenGL 4.5 core: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  try {
    initialiseGl();
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

glm::ivec2 GlfwWindow::framebufferSize() const {
  glm::ivec2 size{0, 0};
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

void GlfwWindow::swapBuffers() {
  glfwSwapBuffers(window_);
}
void GlfwWindow::pollEvents() {
  glfwPollEvents();
}
bool GlfwWindow::shouldClose() const {
  return glfwWindowShouldClose(window_);
}
double GlfwWindow::time() const {
  return glfwGetTime();
}
void GlfwWindow::setVsync(bool on) {
  glfwSwapInterval(on ? 1 : 0);
}
bool GlfwWindow::minimised() const {
  return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE;
}
void GlfwWindow::minimise() {
  glfwIconifyWindow(window_);
}
void GlfwWindow::restore() {
  glfwRestoreWindow(window_);
}

}  // namespace terrasol
