#pragma once
// A shader pack's screen buffers: colortex0..15 as OptiFine keeps them, each a main and an alt texture
// that deferred and composite passes read and write in turn (the written ones flip after each pass),
// in the pack's formats, cleared each frame to its colours, mipmapped where a program asks; and
// depthtex0 (everything drawn) and depthtex1 (before the translucent pass; also depthtex2, there is
// no hand). Only buffers some program reads or writes are made. GL thread only.

#include <array>
#include <bitset>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "render/gl/object.h"
#include "shaderpack/pack_settings.h"

namespace terrasol {

// A 2D texture of `levels` levels (trilinear when more than one), clamped or wrapped at its edges.
gl::Texture packTexture(GLenum format, glm::ivec2 size, int levels, GLenum filter,
                        GLenum wrap = GL_CLAMP_TO_EDGE);

// The GL format of one of OptiFine's buffer formats.
GLenum packInternalFormat(const PackFormat& format);

class PackTargets {
 public:
  PackTargets(glm::ivec2 size, const PackSettings& settings, std::bitset<kPackColorBuffers> used);

  glm::ivec2 size() const { return size_; }
  bool has(int buffer) const { return static_cast<bool>(buffers_[buffer].textures[0]); }
  GLuint main(int buffer) const { return buffers_[buffer].textures[buffers_[buffer].flipped].id(); }
  GLuint alt(int buffer) const { return buffers_[buffer].textures[!buffers_[buffer].flipped].id(); }
  void flip(int buffer) { buffers_[buffer].flipped = !buffers_[buffer].flipped; }
  GLuint depth(int which) const { return which == 0 ? depth0_.id() : depth1_.id(); }

  // The frame's start: main buffers cleared as the settings say (colortex0 to the fog colour).
  void clear(glm::vec3 fogColor);
  // depthtex0 -> depthtex1, before translucent geometry.
  void keepOpaqueDepth();
  void generateMipmaps(int buffer);

  // Binds the framebuffer that draws `buffers` (their main or alt textures) and, with `depth`,
  // depthtex0; the viewport covers the targets.
  void bindDraw(const std::vector<int>& buffers, bool alt, bool depth);
  // Points the framebuffer's read buffer at `buffer`'s main texture (for a copy out).
  void bindRead(int buffer);
  GLuint framebuffer() const { return framebuffer_.id(); }
  // Texels holding NaN or Inf in the float buffers' main and alt textures (reads them back).
  std::size_t nonFinitePixels() const;

 private:
  struct Buffer {
    std::array<gl::Texture, 2> textures;
    bool flipped = false;
    int levels = 1;
  };
  glm::ivec2 size_;
  PackSettings settings_;
  std::array<Buffer, kPackColorBuffers> buffers_;
  gl::Texture depth0_, depth1_;
  gl::Framebuffer framebuffer_;
};

}  // namespace terrasol
