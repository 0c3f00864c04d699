#include "pack_render/pack_targets.h"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>

namespace terrasol {
namespace {

struct NamedFormat {
  std::string_view name;
  GLenum format;
};
#define TERRASOL_FORMAT(x) \
  { #x, GL_##x }
constexpr NamedFormat kGlFormats[] = {
    TERRASOL_FORMAT(R8),          TERRASOL_FORMAT(RG8),
    TERRASOL_FORMAT(RGB8),        TERRASOL_FORMAT(RGBA8),
    TERRASOL_FORMAT(R8_SNORM),    TERRASOL_FORMAT(RG8_SNORM),
    TERRASOL_FORMAT(RGB8_SNORM),  TERRASOL_FORMAT(RGBA8_SNORM),
    TERRASOL_FORMAT(R16),         TERRASOL_FORMAT(RG16),
    TERRASOL_FORMAT(RGB16),       TERRASOL_FORMAT(RGBA16),
    TERRASOL_FORMAT(R16_SNORM),   TERRASOL_FORMAT(RG16_SNORM),
    TERRASOL_FORMAT(RGB16_SNORM), TERRASOL_FORMAT(RGBA16_SNORM),
    TERRASOL_FORMAT(R16F),        TERRASOL_FORMAT(RG16F),
    TERRASOL_FORMAT(RGB16F),      TERRASOL_FORMAT(RGBA16F),
    TERRASOL_FORMAT(R32F),        TERRASOL_FORMAT(RG32F),
    TERRASOL_FORMAT(RGB32F),      TERRASOL_FORMAT(RGBA32F),
    TERRASOL_FORMAT(R8I),         TERRASOL_FORMAT(RG8I),
    TERRASOL_FORMAT(RGB8I),       TERRASOL_FORMAT(RGBA8I),
    TERRASOL_FORMAT(R8UI),        TERRASOL_FORMAT(RG8UI),
    TERRASOL_FORMAT(RGB8UI),      TERRASOL_FORMAT(RGBA8UI),
    TERRASOL_FORMAT(R16I),        TERRASOL_FORMAT(RG16I),
    TERRASOL_FORMAT(RGB16I),      TERRASOL_FORMAT(RGBA16I),
    TERRASOL_FORMAT(R16UI),       TERRASOL_FORMAT(RG16UI),
    TERRASOL_FORMAT(RGB16UI),     TERRASOL_FORMAT(RGBA16UI),
    TERRASOL_FORMAT(R32I),        TERRASOL_FORMAT(RG32I),
    TERRASOL_FORMAT(RGB32I),      TERRASOL_FORMAT(RGBA32I),
    TERRASOL_FORMAT(R32UI),       TERRASOL_FORMAT(RG32UI),
    TERRASOL_FORMAT(RGB32UI),     TERRASOL_FORMAT(RGBA32UI),
    TERRASOL_FORMAT(R3_G3_B2),    TERRASOL_FORMAT(RGB5_A1),
    TERRASOL_FORMAT(RGB10_A2),    TERRASOL_FORMAT(R11F_G11F_B10F),
    TERRASOL_FORMAT(RGB9_E5),
};
#undef TERRASOL_FORMAT

}  // namespace

gl::Texture packTexture(GLenum format, glm::ivec2 size, int levels, GLenum filter, GLenum wrap) {
  gl::Texture t = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), levels, format, size.x, size.y);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER,
                      static_cast<GLint>(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : filter));
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  return t;
}

GLenum packInternalFormat(const PackFormat& format) {
  for (const NamedFormat& f : kGlFormats)
    if (f.name == format.name) return f.format;
  return GL_RGBA8;
}

PackTargets::PackTargets(glm::ivec2 size, const PackSettings& settings, std::bitset<kPackColorBuffers> used)
    : size_(size),
      settings_(settings),
      depth0_(packTexture(GL_DEPTH_COMPONENT32F, size, 1, GL_NEAREST)),
      depth1_(packTexture(GL_DEPTH_COMPONENT32F, size, 1, GL_NEAREST)),
      framebuffer_(gl::Framebuffer::create()) {
  for (int b = 0; b < kPackColorBuffers; ++b) {
    if (!used[b]) continue;
    const PackBuffer& p = settings.buffers[b];
    Buffer& buffer = buffers_[b];
    buffer.levels = p.mipmap ? 1 + static_cast<int>(std::floor(std::log2(std::max(size.x, size.y)))) : 1;
    const GLenum format = packInternalFormat(p.format);
    // Integer formats cannot be filtered.
    const bool integer = p.format.kind == PackFormat::Kind::Int || p.format.kind == PackFormat::Kind::Uint;
    for (gl::Texture& t : buffer.textures)
      t = packTexture(format, size, buffer.levels, integer ? GL_NEAREST : GL_LINEAR);
  }
}

void PackTargets::clear(glm::vec3 fogColor) {
  for (int b = 0; b < kPackColorBuffers; ++b) {
    if (!has(b) || !settings_.buffers[b].clear) continue;
    const glm::vec4 colour = settings_.buffers[b].clearColor.value_or(b == 0   ? glm::vec4(fogColor, 1.0f)
                                                                      : b == 1 ? glm::vec4(1.0f)
                                                                               : glm::vec4(0.0f));
    const PackFormat::Kind kind = settings_.buffers[b].format.kind;
    for (const gl::Texture& t : buffers_[b].textures) {
      if (kind == PackFormat::Kind::Int || kind == PackFormat::Kind::Uint) {
        const glm::ivec4 whole(colour);
        glClearTexImage(t.id(), 0, GL_RGBA_INTEGER, kind == PackFormat::Kind::Int ? GL_INT : GL_UNSIGNED_INT,
                        &whole);
      } else {
        glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, &colour);
      }
    }
    buffers_[b].flipped = false;
  }
  const float far = 1.0f;
  glClearTexImage(depth0_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
  glClearTexImage(depth1_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
}

void PackTargets::keepOpaqueDepth() {
  glCopyImageSubData(depth0_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depth1_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                     size_.x, size_.y, 1);
}

void PackTargets::generateMipmaps(int buffer) {
  if (has(buffer) && buffers_[buffer].levels > 1) glGenerateTextureMipmap(main(buffer));
}

void PackTargets::bindDraw(const std::vector<int>& buffers, bool alt, bool depth) {
  const GLuint fb = framebuffer_.id();
  std::vector<GLenum> draw;
  for (int i = 0; i < kPackMaxDrawBuffers; ++i) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    const int b = i < static_cast<int>(buffers.size()) ? buffers[static_cast<std::size_t>(i)] : -1;
    if (b >= 0 && has(b)) {
      glNamedFramebufferTexture(fb, attachment, alt ? this->alt(b) : main(b), 0);
      draw.push_back(attachment);
    } else {
      glNamedFramebufferTexture(fb, attachment, 0, 0);
      if (i < static_cast<int>(buffers.size())) draw.push_back(GL_NONE);
    }
  }
  glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, depth ? depth0_.id() : 0, 0);
  glNamedFramebufferDrawBuffers(fb, static_cast<GLsizei>(draw.size()), draw.data());
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, size_.x, size_.y);
}

std::size_t PackTargets::nonFinitePixels() const {
  std::size_t bad = 0;
  std::vector<glm::vec4> texels(static_cast<std::size_t>(size_.x * size_.y));
  for (int b = 0; b < kPackColorBuffers; ++b) {
    if (!has(b) || settings_.buffers[b].format.kind != PackFormat::Kind::Float) continue;
    for (const gl::Texture& t : buffers_[b].textures) {
      glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)),
                        texels.data());
      for (const glm::vec4& v : texels)
        bad += !(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w));
    }
  }
  return bad;
}

void PackTargets::bindRead(int buffer) {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, main(buffer), 0);
  glNamedFramebufferReadBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
}

}  // namespace terrasol
