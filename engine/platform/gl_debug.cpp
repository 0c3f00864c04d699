#include "platform/gl_debug.h"

#include <epoxy/gl.h>

#include "core/log.h"

namespace terrasol {
namespace {

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint /*id*/, GLenum severity, GLsizei length,
                              const GLchar* message, const void* user) {
  // Compile and link failures arrive through the program's info log, mapped to file:line (ShaderError).
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  auto* self = static_cast<GlDebugOutput*>(const_cast<void*>(user));
  const std::string text = length >= 0 ? std::string(message, static_cast<std::size_t>(length)) : message;
  self->onMessage(type, severity, text.c_str());
}

const char* errorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "unknown GL error";
  }
}

}  // namespace

void GlDebugOutput::install() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debugCallback, this);
  // Notifications (buffer placement hints and the like) are noise.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
}

void GlDebugOutput::onMessage(unsigned type, unsigned severity, const char* message) {
  const bool isError = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
  if (!isError) {
    logWarning(std::string("GL: ") + message);
    return;
  }
  if (policy_ == GlErrorPolicy::Log) {
    logError(std::string("GL: ") + message);
    return;
  }
  std::lock_guard lock(mutex_);
  errors_.emplace_back(message);
}

void GlDebugOutput::check(const char* where) {
  std::vector<std::string> errors;
  {
    std::lock_guard lock(mutex_);
    errors.swap(errors_);
  }
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    const std::string text = std::string(errorName(e)) + " (from glGetError)";
    if (policy_ == GlErrorPolicy::Log) {
      logError("GL: " + text + " before " + where);
    } else if (errors.empty()) {  // the debug callback normally reported it already
      errors.push_back(text);
    }
  }
  if (errors.empty()) return;
  std::string message = std::string("GL error before ") + where + ":";
  for (const auto& e : errors) message += "\n  " + e;
  throw GlError(message);
}

}  // namespace terrasol
