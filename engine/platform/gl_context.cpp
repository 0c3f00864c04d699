#include "platform/gl_context.h"

#include <epoxy/gl.h>

#include "core/error.h"

namespace terrasol {

void GlContext::initialiseGl() {
  if (epoxy_gl_version() < 45) {
    throw Error("OpenGL 4.5 is required, the driver offers " + std::to_string(epoxy_gl_version() / 10) + "." +
                std::to_string(epoxy_gl_version() % 10));
  }
  debug_.install();
}

std::string GlContext::description() const {
  auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return str(GL_RENDERER) + ", " + str(GL_VERSION);
}

}  // namespace terrasol
