#include "render/gl/render_target.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.h"

namespace terrasol {

RenderTarget::RenderTarget(glm::ivec2 size)
    : size_(size),
      color_(gl::Texture::create(GL_TEXTURE_2D)),
      depth_(gl::Renderbuffer::create()),
      framebuffer_(gl::Framebuffer::create()) {
  if (size.x <= 0 || size.y <= 0) {
    throw Error("render target size must be positive, got " + std::to_string(size.x) + "x" + std::to_string(size.y));
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

Image RenderTarget::readPixels() const {
  Image image(size_.x, size_.y);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.rgba.size()),
                    image.rgba.data());
  const std::size_t row = static_cast<std::size_t>(size_.x) * 4;
  for (int y = 0; y < size_.y / 2; ++y) {
    std::swap_ranges(image.pixel(0, y), image.pixel(0, y) + row, image.pixel(0, size_.y - 1 - y));
  }
  return image;
}

}  // namespace terrasol
