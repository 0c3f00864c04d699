#pragma once
// The cloud layer's map on the GPU: one R8 texel of coverage per cloud cell, repeating. The fancy
// layer's walk reads texels whole (texelFetch); cloud shadows read it filtered, so a shadow's edge is
// soft across a 12-block cell. GL thread only.

#include <glm/vec2.hpp>

#include "core/cloud_layer.h"
#include "render/gl/object.h"

namespace terrasol {

class CloudTexture {
 public:
  explicit CloudTexture(const CloudMap& map);

  GLuint id() const { return texture_.id(); }
  glm::ivec2 size() const { return size_; }

 private:
  gl::Texture texture_;
  glm::ivec2 size_;
};

}  // namespace terrasol
