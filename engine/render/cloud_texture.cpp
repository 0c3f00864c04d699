#include "render/cloud_texture.h"

namespace terrasol {

CloudTexture::CloudTexture(const CloudMap& map)
    : texture_(gl::Texture::create(GL_TEXTURE_2D)), size_(map.width, map.height) {
  glTextureStorage2D(texture_.id(), 1, GL_R8, map.width, map.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Row 0 is the map's first row (z's first cell), as lib/clouds.glsl indexes it.
  glTextureSubImage2D(texture_.id(), 0, 0, 0, map.width, map.height, GL_RED, GL_UNSIGNED_BYTE,
                      map.cover.data());
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

}  // namespace terrasol
