#pragma once
// An offscreen colour (RGBA8) + depth framebuffer, read back as an Image. Headless rendering draws
// here; the window draws into framebuffer 0 with the same code.

#include <glm/vec2.hpp>

#include "assets/image.h"
#include "render/gl/object.h"

namespace terrasol {

// A one-level 2D texture to render into, clamped at its edges and filtered by `filter` (GL_NEAREST or
// GL_LINEAR).
gl::Texture targetTexture(GLenum format, glm::ivec2 size, GLenum filter);

// Reads colour attachment 0 of `framebuffer` (the back buffer for 0), top row first.
Image readFramebuffer(GLuint framebuffer, glm::ivec2 size);

class RenderTarget {
 public:
  // Throws Error for a non-positive size or an incomplete framebuffer.
  explicit RenderTarget(glm::ivec2 size);

  GLuint framebuffer() const { return framebuffer_.id(); }
  glm::ivec2 size() const { return size_; }
  // The colour buffer, top row first (GL stores bottom row first).
  Image readPixels() const;

 private:
  glm::ivec2 size_;
  gl::Texture color_;
  gl::Renderbuffer depth_;
  gl::Framebuffer framebuffer_;
};

}  // namespace terrasol
