#pragma once
// Headless OpenGL 4.5 core through EGL with no surface: tests and tools render into their own
// framebuffers. Works without X or Wayland (Mesa's llvmpipe on CI, a GPU driver where present).

#include <memory>

#include "platform/gl_context.h"

namespace terrasol {

// Tries EGL platforms in order: Mesa surfaceless, EGL devices, the default display. Setting
// TERRASOL_EGL_PLATFORM to "surfaceless", "device" or "default" picks one. Throws Error listing
// what each attempt said when none gives a 4.5 core context.
std::unique_ptr<GlContext> createHeadlessContext(GlErrorPolicy policy = GlErrorPolicy::Throw);

}  // namespace terrasol
