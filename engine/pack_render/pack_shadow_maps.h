#pragma once
// A shader pack's shadow maps, as OptiFine keeps them: shadowtex1 the opaque casters' depth,
// shadowtex0 everything's (the opaque depth copied, then translucent casters drawn over it), and
// shadowcolor0/1 what the shadow program writes, cleared to white. GL thread only.

#include <array>
#include <vector>

#include "render/gl/object.h"

namespace terrasol {

class PackShadowMaps {
 public:
  explicit PackShadowMaps(int resolution);

  int resolution() const { return resolution_; }
  GLuint depth(int which) const { return depth_[static_cast<std::size_t>(which)].id(); }    // shadowtexN
  GLuint colour(int which) const { return colour_[static_cast<std::size_t>(which)].id(); }  // shadowcolorN

  // Clears every map and sets the viewport, depth test and write.
  void begin();
  // Binds the framebuffer of pass 0 (opaque casters into shadowtex1) or 1 (translucent ones into
  // shadowtex0), its colour outputs the program's `drawBuffers` (shadowcolor0/1).
  void bindPass(int pass, const std::vector<int>& drawBuffers);
  // shadowtex1 -> shadowtex0, between the passes.
  void copyOpaque();

 private:
  int resolution_;
  std::array<gl::Texture, 2> depth_, colour_;
  std::array<gl::Framebuffer, 2> framebuffers_;
};

}  // namespace terrasol
