#include "render/gbuffer.h"

#include <string>

#include "core/error.h"
#include "render/gl/render_target.h"
#include "render/gl_slots.h"

namespace terrasol {
namespace {

gl::Texture makeTarget(GLenum format, glm::ivec2 size) {
  return targetTexture(format, size, GL_NEAREST);
}

void checkComplete(GLuint framebuffer, const char* name) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    std::string message = name;
    message += " framebuffer incomplete, status ";
    message += std::to_string(status);
    throw Error(message);
  }
}

}  // namespace

GBuffer::GBuffer(glm::ivec2 size, GBufferContents contents)
    : size_(size),
      contents_(contents),
      geometry_(gl::Framebuffer::create()),
      lighting_(gl::Framebuffer::create()),
      translucent_(gl::Framebuffer::create()),
      decal_(gl::Framebuffer::create()) {
  if (size.x <= 0 || size.y <= 0) {
    std::string message = "G-buffer size must be positive, got ";
    message += std::to_string(size.x) + "x" + std::to_string(size.y);
    throw Error(message);
  }
  std::array<GLenum, gbuffer::kTargets> drawBuffers{};
  for (int i = 0; i < gbuffer::kTargets; ++i) {
    const GLenum format = contents.format(i);
    if (format == GL_NONE) continue;  // left out: its draw buffer stays GL_NONE, writes go nowhere
    targets_[static_cast<std::size_t>(i)] = makeTarget(format, size);
    glNamedFramebufferTexture(geometry_.id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), target(i), 0);
    drawBuffers[static_cast<std::size_t>(i)] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
  }
  depth_ = makeTarget(gbuffer::kDepthFormat, size);
  scene_ = makeTarget(GL_RGBA16F, size);
  glNamedFramebufferTexture(geometry_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  glNamedFramebufferDrawBuffers(geometry_.id(), gbuffer::kTargets, drawBuffers.data());
  lightingDepth_ = makeTarget(gbuffer::kDepthFormat, size);
  glNamedFramebufferTexture(lighting_.id(), GL_COLOR_ATTACHMENT0, scene_.id(), 0);
  glNamedFramebufferTexture(lighting_.id(), GL_DEPTH_ATTACHMENT, lightingDepth_.id(), 0);
  glNamedFramebufferTexture(translucent_.id(), GL_COLOR_ATTACHMENT0, scene_.id(), 0);
  glNamedFramebufferTexture(translucent_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  reactive_ = makeTarget(GL_R8, size);
  glNamedFramebufferTexture(translucent_.id(), GL_COLOR_ATTACHMENT0 + slots::kOutReactive, reactive_.id(), 0);
  glNamedFramebufferTexture(decal_.id(), GL_COLOR_ATTACHMENT0, target(gbuffer::kAlbedo), 0);
  checkComplete(geometry_.id(), "G-buffer");
  checkComplete(decal_.id(), "decal");
  checkComplete(lighting_.id(), "lighting");
  checkComplete(translucent_.id(), "translucent");
}

GBufferPixels GBuffer::read() const {
  GBufferPixels out;
  out.size = size_;
  const std::size_t pixels = static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y);
  out.depth.resize(pixels);
  out.normals.resize(pixels);
  out.scene.resize(pixels);
  out.light.resize(pixels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  auto bytes = [](const auto& v) { return static_cast<GLsizei>(v.size() * sizeof(v[0])); };
  glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, bytes(out.depth), out.depth.data());
  glGetTextureImage(target(gbuffer::kNormals), 0, GL_RGBA, GL_FLOAT, bytes(out.normals), out.normals.data());
  glGetTextureImage(scene_.id(), 0, GL_RGBA, GL_FLOAT, bytes(out.scene), out.scene.data());
  glGetTextureImage(target(gbuffer::kLight), 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes(out.light),
                    out.light.data());
  return out;
}

void GBuffer::copyDepthForLighting() const {
  glCopyImageSubData(depth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, lightingDepth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                     size_.x, size_.y, 1);
}

void GBuffer::bindForReading() const {
  for (int i = 0; i < gbuffer::kTargets; ++i)
    glBindTextureUnit(static_cast<GLuint>(i), target(i));  // 0 if left out
  glBindTextureUnit(gbuffer::kDepthUnit, depth_.id());
}

}  // namespace terrasol
