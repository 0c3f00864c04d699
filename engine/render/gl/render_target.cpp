#include "render/gl/render_target.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.h"

namespace terrasol {

gl::Texture targetTexture(GLenum format, glm::ivec2 size, GLenum filter) {
  gl::Texture texture = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, format, size.x, size.y);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

RenderTarget::RenderTarget(glm::ivec2 size)
    : size_(size),
      color_(gl::Texture::create(GL_TEXTURE_2D)),
      depth_(gl::Renderbuffer::create()),
      framebuffer_(gl::Framebuffer::create()) {
  if (size.x <= 0 || size.y <= 0) {
    throw Error("render target size must be positive, got " + std::to_string(size.x) + "x" +
                std::to_string(size.y));
  }
  glTextureStorage2D(color_.id(), 1, GL_RGBA8, size.x, size.y);
  glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT24, size.x, size.y);
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("offscreen framebuffer incomplete, status " + std::to_string(status));
  }
}

Image readFramebuffer(GLuint framebuffer, glm::ivec2 size) {
  Image image(size.x, size.y);
  if (size.x <= 0 || size.y <= 0) return image;
  glNamedFramebufferReadBuffer(framebuffer, framebuffer == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadnPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.rgba.size()),
                image.rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  const std::size_t row = static_cast<std::size_t>(size.x) * 4;
  for (int y = 0; y < size.y / 2; ++y) {  // GL's rows run bottom to top
    std::swap_ranges(image.pixel(0, y), image.pixel(0, y) + row, image.pixel(0, size.y - 1 - y));
  }
  return image;
}

Image RenderTarget::readPixels() const {
  return readFramebuffer(framebuffer_.id(), size_);
}

}  // namespace terrasol
