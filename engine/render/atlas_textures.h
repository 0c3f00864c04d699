#pragma once
// The three block atlases on the GPU, with every mip level built on the CPU (assets/atlas.h):
// albedo as sRGB (decoded to linear when sampled), normal and specular as plain UNORM (LabPBR data is
// linear, and alpha is data, never premultiplied). Specular is sampled nearest at every level so
// metal ids and emission flags are never interpolated.

#include "assets/atlas.h"
#include "render/gl/object.h"

namespace terrasol {

// A 2D texture from an image and its mip levels (largest first), rows top first as Image stores them.
gl::Texture uploadTexture(const std::vector<Image>& levels, GLenum format, GLenum minFilter,
                          GLenum magFilter);

class AtlasTextures {
 public:
  explicit AtlasTextures(const Atlas& atlas);

  GLuint albedo() const { return albedo_.id(); }
  GLuint normal() const { return normal_.id(); }
  GLuint specular() const { return specular_.id(); }
  int levels() const { return levels_; }

 private:
  gl::Texture albedo_, normal_, specular_;
  int levels_;
};

}  // namespace terrasol
