#pragma once
// What a shader pack's sky programs draw, as vanilla's sky does: gbuffers_skybasic a disc of the sky's
// colour 16 blocks above the eye and a dark one 16 below; gbuffers_skytextured the sun (30 blocks
// across at 100) and the moon (20), turned with the celestial angle and the pack's sun path, each
// with its texture (a disc of our own: packs' sun.png and moon_phases.png are not read yet). Player
// space, around the camera. GL thread only.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/gl/object.h"

namespace terrasol {

class PackSky {
 public:
  PackSky();

  // Rebuilds the vertices: `sky` the disc's colour (sRGB), `celestial` vanilla's sky rotation (no view).
  void update(glm::vec3 sky, const glm::mat4& celestial);

  void drawSky() const;  // the discs
  // Each binds its texture to `unit` first.
  void drawSun(GLuint unit) const;
  void drawMoon(GLuint unit) const;

 private:
  gl::Buffer vertices_;
  gl::VertexArray layout_;
  gl::Texture sun_, moon_;
};

}  // namespace terrasol
