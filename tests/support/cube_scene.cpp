#include "support/cube_scene.h"

#include <array>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/paths.h"
#include "render/gl/program.h"
#include "render/gl_slots.h"

namespace terrasol {
namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 color;
};

// Appends the 36 vertices (12 counter-clockwise triangles) of one box.
void appendBox(std::vector<Vertex>& out, const CubeInstance& cube) {
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {-1, 1}) {
      glm::vec3 n(0.0f);
      n[axis] = static_cast<float>(sign);
      // Two tangent axes chosen so (u x v) == n, which makes the quad counter-clockwise from outside.
      glm::vec3 u(0.0f), v(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = static_cast<float>(sign);
      const std::array<glm::vec2, 6> corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}}};
      for (const glm::vec2 c : corners) {
        const glm::vec3 local = n + c.x * u + c.y * v;
        out.push_back({cube.center + local * cube.halfSize, n, cube.color});
      }
    }
  }
}

}  // namespace

ShaderPreprocessor CubeScene::sceneShaders() {
  const std::filesystem::path roots[] = {std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests/support/shaders",
                                         shaderDir()};
  return ShaderPreprocessor([roots](const std::string& path) -> std::optional<std::string> {
    std::error_code ec;
    for (const auto& root : roots)
      if (std::filesystem::is_regular_file(root / path, ec)) return readTextFile(root / path);
    return std::nullopt;
  });
}

CubeScene::CubeScene(const ShaderPreprocessor& shaders, const std::vector<CubeInstance>& cubes)
    : program_(buildProgram(shaders, {{GL_VERTEX_SHADER, "cubes.vert"}, {GL_FRAGMENT_SHADER, "cubes.frag"}},
                            slotDefines())),
      vertices_(gl::Buffer::create()),
      layout_(gl::VertexArray::create()) {
  std::vector<Vertex> data;
  for (const auto& cube : cubes) appendBox(data, cube);
  vertexCount_ = static_cast<GLsizei>(data.size());
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(data.size() * sizeof(Vertex)), data.data(), 0);

  glVertexArrayVertexBuffer(layout_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
  const std::array<std::pair<int, GLuint>, 3> attributes = {{
      {slots::kAttribPosition, offsetof(Vertex, position)},
      {slots::kAttribNormal, offsetof(Vertex, normal)},
      {slots::kAttribColor, offsetof(Vertex, color)},
  }};
  for (const auto& [location, offset] : attributes) {
    glEnableVertexArrayAttrib(layout_.id(), location);
    glVertexArrayAttribFormat(layout_.id(), location, 3, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(layout_.id(), location, 0);
  }
}

std::vector<CubeInstance> CubeScene::standardCubes() {
  return {
      {{0.0f, -0.5f, 0.0f}, {8.0f, 0.5f, 8.0f}, {0.45f, 0.62f, 0.32f}},  // grass-green slab
      {{-3.0f, 1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}, {0.80f, 0.22f, 0.18f}},
      {{0.5f, 0.75f, 1.5f}, {0.75f, 0.75f, 0.75f}, {0.95f, 0.95f, 0.92f}},
      {{2.5f, 1.5f, -2.5f}, {1.0f, 1.5f, 1.0f}, {0.25f, 0.40f, 0.85f}},
      {{-0.5f, 0.5f, -4.0f}, {0.5f, 0.5f, 0.5f}, {0.95f, 0.75f, 0.20f}},
      {{4.5f, 0.5f, 2.5f}, {0.5f, 0.5f, 0.5f}, {0.55f, 0.35f, 0.75f}},
  };
}

void CubeScene::draw(GLuint framebuffer, glm::ivec2 size, const Camera& camera, glm::vec3 towardLight) const {
  if (size.x <= 0 || size.y <= 0) return;  // minimised window: nothing to draw
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  // Sky colour in sRGB: the clear writes straight to the sRGB-encoded target.
  const float sky[4] = {0.55f, 0.72f, 0.95f, 1.0f};
  const float depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, sky);
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &depth);

  const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
  const glm::mat4 viewProjection = camera.projection(aspect) * camera.view();
  const float lengthToLight = glm::length(towardLight);
  const glm::vec3 toLight = lengthToLight > 1e-6f ? towardLight / lengthToLight : glm::vec3(0.0f, 1.0f, 0.0f);
  glProgramUniformMatrix4fv(program_.id(), glGetUniformLocation(program_.id(), "u_viewProjection"), 1,
                            GL_FALSE, glm::value_ptr(viewProjection));
  glProgramUniform3fv(program_.id(), glGetUniformLocation(program_.id(), "u_toLight"), 1,
                      glm::value_ptr(toLight));

  glUseProgram(program_.id());
  glBindVertexArray(layout_.id());
  glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace terrasol
