#pragma once
// One interface for an OpenGL 4.5 core context, windowed (GLFW) or headless (EGL). The renderer
// never knows which: it draws into whatever framebuffer its caller gives it.

#include <glm/vec2.hpp>
#include <memory>
#include <string>

#include "platform/gl_debug.h"

namespace terrasol {

class GlContext {
 public:
  explicit GlContext(GlErrorPolicy policy) : debug_(policy) {}
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Size of the default framebuffer in pixels; {0, 0} when there is none (headless) or the window
  // is minimised. Callers skip drawing for a zero size.
  virtual glm::ivec2 framebufferSize() const = 0;
  // Presents the default framebuffer; a no-op headless.
  virtual void swapBuffers() = 0;

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string description() const;
  // Throws GlError (tests, tools) or logs (game) for any GL error reported since the last check.
  void checkErrors(const char* where) { debug_.check(where); }

 protected:
  // Implementations call this once their context is current: installs debug output.
  void initialiseGl();

 private:
  GlDebugOutput debug_;
};

}  // namespace terrasol
