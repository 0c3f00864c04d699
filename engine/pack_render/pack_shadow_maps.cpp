#include "pack_render/pack_shadow_maps.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "pack_render/pack_targets.h"

namespace terrasol {

PackShadowMaps::PackShadowMaps(int resolution) : resolution_(resolution) {
  const glm::ivec2 size(resolution);
  for (gl::Texture& t : depth_) t = packTexture(GL_DEPTH_COMPONENT32F, size, 1, GL_NEAREST);
  for (gl::Texture& t : colour_) t = packTexture(GL_RGBA8, size, 1, GL_LINEAR);
  for (std::size_t pass = 0; pass < 2; ++pass) {
    framebuffers_[pass] = gl::Framebuffer::create();
    const GLuint fb = framebuffers_[pass].id();
    glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, depth_[1 - pass].id(), 0);
    for (std::size_t c = 0; c < 2; ++c)
      glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(c), colour_[c].id(), 0);
  }
}

void PackShadowMaps::begin() {
  const glm::vec4 white(1.0f);
  const float far = 1.0f;
  for (const gl::Texture& c : colour_) glClearTexImage(c.id(), 0, GL_RGBA, GL_FLOAT, &white);
  for (const gl::Texture& d : depth_) glClearTexImage(d.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
  glViewport(0, 0, resolution_, resolution_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
}

void PackShadowMaps::bindPass(int pass, const std::vector<int>& drawBuffers) {
  std::vector<GLenum> draw;
  for (int i : drawBuffers) draw.push_back(i < 2 ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i) : GL_NONE);
  const GLuint fb = framebuffers_[static_cast<std::size_t>(pass)].id();
  glNamedFramebufferDrawBuffers(fb, static_cast<GLsizei>(draw.size()), draw.data());
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
}

void PackShadowMaps::copyOpaque() {
  glCopyImageSubData(depth(1), GL_TEXTURE_2D, 0, 0, 0, 0, depth(0), GL_TEXTURE_2D, 0, 0, 0, 0, resolution_,
                     resolution_, 1);
}

}  // namespace terrasol
