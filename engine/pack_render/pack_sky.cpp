#include "pack_render/pack_sky.h"

#include <array>
#include <cmath>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <numbers>
#include <vector>

#include "render/gl_slots.h"

namespace terrasol {
namespace {

struct SkyVertex {
  glm::vec3 position;
  glm::vec4 colour;
  glm::vec2 uv;
};

constexpr int kDiscSides = 16;
constexpr float kDiscRadius = 512.0f;
constexpr float kDiscHeight = 16.0f;
constexpr float kBodyDistance = 100.0f;
constexpr float kSunHalfSize = 30.0f;
constexpr float kMoonHalfSize = 20.0f;
constexpr int kSkyVertices = 2 * 3 * kDiscSides;  // two discs of triangles
constexpr int kBodyVertices = 6;                  // a quad as two triangles
constexpr int kTextureSize = 32;

// A round body on a clear square: white fading at its rim, `shade` inside.
gl::Texture discTexture(float shade) {
  std::vector<std::uint8_t> texels(kTextureSize * kTextureSize * 4);
  for (int y = 0; y < kTextureSize; ++y) {
    for (int x = 0; x < kTextureSize; ++x) {
      const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / float(kTextureSize) * 2.0f - 1.0f;
      const float cover = std::clamp((0.8f - std::sqrt(p.x * p.x + p.y * p.y)) * 12.0f, 0.0f, 1.0f);
      std::uint8_t* t = &texels[static_cast<std::size_t>((y * kTextureSize + x) * 4)];
      t[0] = t[1] = t[2] = static_cast<std::uint8_t>(std::lround(255.0f * shade * cover));
      t[3] = static_cast<std::uint8_t>(std::lround(255.0f * cover));
    }
  }
  gl::Texture texture = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, GL_RGBA8, kTextureSize, kTextureSize);
  glTextureSubImage2D(texture.id(), 0, 0, 0, kTextureSize, kTextureSize, GL_RGBA, GL_UNSIGNED_BYTE,
                      texels.data());
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return texture;
}

void disc(std::vector<SkyVertex>& out, float height, glm::vec4 colour) {
  for (int i = 0; i < kDiscSides; ++i) {
    const auto at = [&](int k) {
      const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / kDiscSides;
      return glm::vec3(kDiscRadius * std::cos(a), height, kDiscRadius * std::sin(a));
    };
    // Facing the eye: counter-clockwise seen from the camera at the centre.
    const bool above = height > 0.0f;
    out.push_back({{0.0f, height, 0.0f}, colour, {0.5f, 0.5f}});
    out.push_back({at(above ? i + 1 : i), colour, {0.0f, 0.0f}});
    out.push_back({at(above ? i : i + 1), colour, {0.0f, 0.0f}});
  }
}

void body(std::vector<SkyVertex>& out, const glm::mat4& celestial, float up, float halfSize) {
  // Vanilla: a square `halfSize` each way at y = +-100 in the rotated sky.
  const glm::vec4 white(1.0f);
  const glm::vec3 c[4] = {{-halfSize, up, -halfSize},
                          {halfSize, up, -halfSize},
                          {halfSize, up, halfSize},
                          {-halfSize, up, halfSize}};
  const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k : {0, 1, 2, 0, 2, 3})
    out.push_back({glm::vec3(celestial * glm::vec4(c[k], 1.0f)), white, uv[k]});
}

}  // namespace

PackSky::PackSky()
    : vertices_(gl::Buffer::create()),
      layout_(gl::VertexArray::create()),
      sun_(discTexture(1.0f)),
      moon_(discTexture(0.75f)) {
  glNamedBufferStorage(vertices_.id(), sizeof(SkyVertex) * (kSkyVertices + 2 * kBodyVertices), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  const GLuint vao = layout_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(SkyVertex));
  const auto attribute = [&](int slot, int size, std::size_t offset) {
    glEnableVertexArrayAttrib(vao, static_cast<GLuint>(slot));
    glVertexArrayAttribFormat(vao, static_cast<GLuint>(slot), size, GL_FLOAT, GL_FALSE,
                              static_cast<GLuint>(offset));
    glVertexArrayAttribBinding(vao, static_cast<GLuint>(slot), 0);
  };
  attribute(slots::kAttribPosition, 3, offsetof(SkyVertex, position));
  attribute(slots::kAttribColor, 4, offsetof(SkyVertex, colour));
  attribute(slots::kAttribUv, 2, offsetof(SkyVertex, uv));
}

void PackSky::update(glm::vec3 sky, const glm::mat4& celestial) {
  std::vector<SkyVertex> v;
  disc(v, kDiscHeight, glm::vec4(sky, 1.0f));
  disc(v, -kDiscHeight, glm::vec4(sky * glm::vec3(0.2f, 0.2f, 0.6f), 1.0f));  // vanilla's dark void
  body(v, celestial, kBodyDistance, kSunHalfSize);
  body(v, celestial, -kBodyDistance, kMoonHalfSize);
  glNamedBufferSubData(vertices_.id(), 0, static_cast<GLsizeiptr>(v.size() * sizeof(SkyVertex)), v.data());
}

void PackSky::drawSky() const {
  glBindVertexArray(layout_.id());
  glDrawArrays(GL_TRIANGLES, 0, kSkyVertices);
}

void PackSky::drawSun(GLuint unit) const {
  glBindTextureUnit(unit, sun_.id());
  glBindVertexArray(layout_.id());
  glDrawArrays(GL_TRIANGLES, kSkyVertices, kBodyVertices);
}

void PackSky::drawMoon(GLuint unit) const {
  glBindTextureUnit(unit, moon_.id());
  glBindVertexArray(layout_.id());
  glDrawArrays(GL_TRIANGLES, kSkyVertices + kBodyVertices, kBodyVertices);
}

}  // namespace terrasol
