#include "render/atlas_textures.h"

namespace terrasol {

gl::Texture uploadTexture(const std::vector<Image>& levels, GLenum format, GLenum minFilter,
                          GLenum magFilter) {
  gl::Texture texture = gl::Texture::create(GL_TEXTURE_2D);
  const Image& base = levels.front();
  glTextureStorage2D(texture.id(), static_cast<GLsizei>(levels.size()), format, base.width, base.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const Image& image = levels[level];
    // Uploaded as is: texture row 0 is the image's top row, where atlas UVs put v = 0.
    glTextureSubImage2D(texture.id(), static_cast<GLint>(level), 0, 0, image.width, image.height, GL_RGBA,
                        GL_UNSIGNED_BYTE, image.rgba.data());
  }
  glTextureParameteri(texture.id(), GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

AtlasTextures::AtlasTextures(const Atlas& atlas)
    // Magnified nearest: pixel art stays crisp up close.
    : albedo_(uploadTexture(atlas.albedo, GL_SRGB8_ALPHA8, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST)),
      normal_(uploadTexture(atlas.normal, GL_RGBA8, GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST)),
      specular_(uploadTexture(atlas.specular, GL_RGBA8, GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST)),
      levels_(atlas.levels()) {}

}  // namespace terrasol
