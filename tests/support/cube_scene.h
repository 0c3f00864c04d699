#pragma once
// The foundation's test scene: a few solid cubes on a ground slab, lit by one directional light and
// a sky/ground ambient, drawn forward into any framebuffer. Later passes replace it; it stays as the
// simplest end-to-end check of the platform, shader and image paths.

#include <vector>

#include "assets/shader_source.h"
#include "core/camera.h"
#include "render/gl/object.h"

namespace terrasol {

struct CubeInstance {
  glm::vec3 center;
  glm::vec3 halfSize;
  glm::vec3 color;  // sRGB
};

class CubeScene {
 public:
  CubeScene(const ShaderPreprocessor& shaders, const std::vector<CubeInstance>& cubes);

  // Its shaders (tests/support/shaders), which include the engine's shaders/lib.
  static ShaderPreprocessor sceneShaders();

  // Five coloured cubes on a 16x16 slab centred on the origin, top of the slab at y = 0.
  static std::vector<CubeInstance> standardCubes();

  // Draws into `framebuffer` (0 for a window) over its whole `size`. `towardLight` points at the light.
  void draw(GLuint framebuffer, glm::ivec2 size, const Camera& camera, glm::vec3 towardLight) const;

 private:
  gl::Program program_;
  gl::Buffer vertices_;
  gl::VertexArray layout_;
  GLsizei vertexCount_ = 0;
};

}  // namespace terrasol
