#include "platform/egl/egl_context.h"

// EGL straight from libEGL: libepoxy cannot resolve EGL 1.5 entry points before a display exists.
// GL calls still go through epoxy, which notices the current EGL context by itself.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"

namespace terrasol {
namespace {

std::string eglErrorText() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return buf;
}

bool hasClientExtension(const char* name) {
  const char* exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  return exts && std::strstr(exts, name) != nullptr;
}

EGLDisplay surfacelessDisplay() {
  if (!hasClientExtension("EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
  return eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

EGLDisplay deviceDisplay() {
  // NVIDIA's EGL names enumeration as part of EGL_EXT_device_base.
  if (!hasClientExtension("EGL_EXT_platform_device") ||
      !(hasClientExtension("EGL_EXT_device_enumeration") || hasClientExtension("EGL_EXT_device_base"))) {
    return EGL_NO_DISPLAY;
  }
  const auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  EGLDeviceEXT devices[8];
  EGLint count = 0;
  if (!queryDevices || !queryDevices(8, devices, &count) || count == 0) return EGL_NO_DISPLAY;
  return eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
}

class EglContext final : public GlContext {
 public:
  EglContext(GlErrorPolicy policy, EGLDisplay display, EGLContext context)
      : GlContext(policy), display_(display), context_(context) {
    try {
      initialiseGl();
    } catch (...) {
      release();  // the destructor does not run for a half-built object
      throw;
    }
  }
  ~EglContext() override { release(); }

  glm::ivec2 framebufferSize() const override { return {0, 0}; }
  void swapBuffers() override {}

 private:
  void release() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  EGLDisplay display_;
  EGLContext context_;
};

// Initialises `display` and makes a current 4.5 core context on it; returns nullptr and fills `why`.
EGLContext createContext(EGLDisplay display, std::string& why) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return why = "eglInitialize: " + eglErrorText(), nullptr;
  if (!eglBindAPI(EGL_OPENGL_API)) return why = "eglBindAPI(OpenGL): " + eglErrorText(), nullptr;
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                            4,
                            EGL_CONTEXT_MINOR_VERSION,
                            5,  // 4.6 is refused by Mesa 22's llvmpipe
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_CONTEXT_OPENGL_DEBUG,
                            EGL_TRUE,
                            EGL_NONE};
  // Surfaceless rendering needs no config (EGL_KHR_no_config_context) and no surface.
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) return why = "eglCreateContext(4.5 core): " + eglErrorText(), nullptr;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    why = "eglMakeCurrent(no surface): " + eglErrorText();
    eglDestroyContext(display, context);
    return nullptr;
  }
  return context;
}

}  // namespace

std::unique_ptr<GlContext> createHeadlessContext(GlErrorPolicy policy) {
  struct Platform {
    const char* name;
    EGLDisplay (*open)();
  };
  const Platform platforms[] = {
      {"surfaceless", surfacelessDisplay},
      {"device", deviceDisplay},
      {"default", [] { return eglGetDisplay(EGL_DEFAULT_DISPLAY); }},
  };
  const char* only = std::getenv("TERRASOL_EGL_PLATFORM");
  std::string failures;
  for (const auto& platform : platforms) {
    if (only && *only && std::strcmp(only, platform.name) != 0) continue;
    EGLDisplay display = platform.open();
    std::string why = "no display";
    if (display != EGL_NO_DISPLAY) {
      if (EGLContext context = createContext(display, why)) {
        return std::make_unique<EglContext>(policy, display, context);
      }
      eglTerminate(display);
    }
    failures += std::string("\n  ") + platform.name + ": " + why;
  }
  throw Error("cannot create a headless OpenGL 4.5 core context:" + failures);
}

}  // namespace terrasol
