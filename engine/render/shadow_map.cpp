#include "render/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "core/error.h"

namespace terrasol {

ShadowView shadowViewFor(int resolution, float mapDistance, glm::vec3 toLight, glm::dvec3 camera,
                         glm::dvec3 centre) {
  const glm::dvec3 z = glm::normalize(glm::dvec3(toLight));
  const glm::dvec3 hint = std::abs(z.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 x = glm::normalize(glm::cross(hint, z));
  const glm::dvec3 y = glm::cross(z, x);
  const double distance = std::max(static_cast<double>(mapDistance), 0.5);
  const double texel = 2.0 * distance / std::max(resolution, 1);
  // The centre in light space, snapped to whole texels: the map moves in whole texels.
  const glm::dvec2 snapped = glm::floor(glm::dvec2(glm::dot(centre, x), glm::dot(centre, y)) / texel) * texel;
  const glm::dvec2 shift =
      glm::dvec2(glm::dot(camera, x), glm::dot(camera, y)) - snapped;  // small: safe in float

  glm::mat4 view(1.0f);  // rows x, y, z: camera-relative world -> light space
  for (int i = 0; i < 3; ++i) {
    view[i][0] = static_cast<float>(x[i]);
    view[i][1] = static_cast<float>(y[i]);
    view[i][2] = static_cast<float>(z[i]);
  }
  const glm::mat4 recentre = glm::translate(glm::mat4(1.0f), glm::vec3(shift, 0.0));
  const float d = static_cast<float>(distance);
  // Light-space z grows towards the light: keep from `distance` below the camera to far above it.
  const glm::mat4 ortho = glm::ortho(-d, d, -d, d, -(d + kShadowCasterReach), d);
  ShadowView v;
  v.matrix = ortho * recentre * view;
  v.toLight = glm::vec3(z);
  v.depthRange = 2.0f * d + kShadowCasterReach;
  v.texelWorld = static_cast<float>(texel);
  return v;
}

namespace {

gl::Texture depthArray(int resolution, int layers) {
  gl::Texture depth = gl::Texture::create(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(depth.id(), 1, GL_DEPTH_COMPONENT32F, resolution, resolution, layers);
  // Hardware comparison: each tap returns the lit fraction of its 2x2 texels.
  glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTextureParameteri(depth.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(depth.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(depth.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(depth.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return depth;
}

void checkComplete(GLuint framebuffer, int resolution) {
  if (glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("shadow map framebuffer incomplete at " + std::to_string(resolution) + " texels");
  }
}

}  // namespace

void ShadowMap::ensure(int resolution, int layers) {
  if (resolution == resolution_ && layers == layers_) return;
  depth_ = depthArray(resolution, layers);
  translucentDepth_ = depthArray(resolution, layers);
  transmittance_ = gl::Texture::create(GL_TEXTURE_2D_ARRAY);
  // One nearest fetch gives the lookup both the colour and the depth it applies below; 16 bits hold the
  // depth to about 0.005 blocks of a 300-block range.
  glTextureStorage3D(transmittance_.id(), 1, GL_RGBA16, resolution, resolution, layers);
  glTextureParameteri(transmittance_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(transmittance_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(transmittance_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(transmittance_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  for (int layer = 0; layer < layers; ++layer) {
    gl::Framebuffer& opaque = framebuffers_[static_cast<std::size_t>(layer)];
    opaque = gl::Framebuffer::create();
    glNamedFramebufferTextureLayer(opaque.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0, layer);
    glNamedFramebufferDrawBuffer(opaque.id(), GL_NONE);
    checkComplete(opaque.id(), resolution);
    gl::Framebuffer& translucent = translucentFramebuffers_[static_cast<std::size_t>(layer)];
    translucent = gl::Framebuffer::create();
    glNamedFramebufferTextureLayer(translucent.id(), GL_DEPTH_ATTACHMENT, translucentDepth_.id(), 0, layer);
    glNamedFramebufferTextureLayer(translucent.id(), GL_COLOR_ATTACHMENT0, transmittance_.id(), 0, layer);
    checkComplete(translucent.id(), resolution);
  }
  resolution_ = resolution;
  layers_ = layers;
}

}  // namespace terrasol
